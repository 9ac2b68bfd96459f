import { expect, test } from '@playwright/test';
import { mkdirSync, writeFileSync } from 'node:fs';
import type { Vec3, ViewOptions, ViewSummary } from './sky';
import type { ViewRequest } from '../lighting/lighting';
import { cloudSunTransmittance } from '../../../src/render/daylight';

/**
 * SunOptions.cloudCover in real pictures: the generated sky under cloudCover 1 is the CIE standard
 * overcast sky (Moon & Spencer 1942, "Illumination from a non-uniform sky": L(θ) = L_z·(1 + 2 cos θ)/3,
 * three times brighter at the zenith than at the horizon) with no sun disk; and the sea's glint
 * dims as the direct sunlight does under N/8 oktas (Kasten & Czeplak 1980, daylight.ts).
 */

const luminance = ([r, g, b]: Vec3): number => 0.2126 * r + 0.7152 * g + 0.0722 * b;

test('cloudCover 1: the sky is the overcast sky, 3× brighter at the zenith than at the horizon, with no sun disk; bad covers throw', async ({ page }) => {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/sky/sky.html');
  await expect(page).toHaveTitle('ready');
  const view = (direction: Vec3, options: ViewOptions): Promise<ViewSummary> =>
    page.evaluate(([d, o]) => window.skyHarness.view(d, o), [direction, options] as const);
  const sunView: ViewOptions = { fov: 10, size: 33 }; // 0.3° per pixel, the disk 0.8° across

  await page.evaluate(() => window.skyHarness.create({ sunElevation: 30, sunAzimuth: 40 }));
  const sun = await page.evaluate(() => window.skyHarness.sunDirection());
  const clearSun = await view(sun, sunView);
  // The clear sky: the disk, HDR, far above the sky around it.
  expect(luminance(clearSun.brightest.value)).toBeGreaterThan(5 * luminance(clearSun.mean));

  const rejected = await page.evaluate(() => [2, NaN, -0.1].map((cover) => window.skyHarness.setCloudCover(cover)));
  for (const { error, cloudCover } of rejected) {
    expect(error).toMatch(/^ParameterError: .*cloudCover/);
    expect(error).toContain('from 0 (clear) to 1 (overcast)');
    expect(cloudCover).toBe(0); // the last good cover stays
  }

  expect((await page.evaluate(() => window.skyHarness.setCloudCover(1))).error).toBeNull();
  // Through SkyBackground, i.e. the 8-bit RGBM cube the sea reflects: the zenith, and a band 1° above
  // the horizon (cos θ = sin 1°: L = L_z·(1 + 0.035)/3), in a narrow view towards the sun's azimuth
  // and away from it (the overcast sky is the same in every azimuth).
  const zenith = luminance((await view([0, 1, 0], { fov: 2, size: 9 })).mean);
  const horizons = await Promise.all([40, 220].map(async (azimuth) => {
    const a = (azimuth * Math.PI) / 180;
    const e = (1 * Math.PI) / 180;
    return luminance((await view([Math.cos(e) * Math.cos(a), Math.sin(e), Math.cos(e) * Math.sin(a)], { fov: 1, size: 9 })).mean);
  }));
  const ratios = horizons.map((horizon) => zenith / horizon);
  console.log(`overcast: zenith ${zenith.toFixed(4)}, 1° above the horizon ${horizons.map((h) => h.toFixed(4)).join(' / ')}, ratios ${ratios.map((r) => r.toFixed(3)).join(' / ')} (Moon & Spencer: 3 at the horizon, ${(3 / (1 + 2 * Math.sin(Math.PI / 180))).toFixed(3)} at 1°)`);
  for (const ratio of ratios) expect(Math.abs(ratio / 3 - 1)).toBeLessThan(0.1);
  // Grey: no channel more than 10 % off the others' mean (the clear sky's zenith is blue, B ≈ 3 R).
  const zenithColour = (await view([0, 1, 0], { fov: 2, size: 9 })).mean;
  const meanChannel = (zenithColour[0] + zenithColour[1] + zenithColour[2]) / 3;
  for (const c of zenithColour) expect(Math.abs(c / meanChannel - 1)).toBeLessThan(0.1);
  // The sun disk is gone: towards the sun the view (25° to 35° up) is the overcast sky's smooth
  // gradient, its brightest pixel within 10 % of its mean (clear: more than 5×) and its centre,
  // where the disk was, the mean's to 2 % (the gradient is linear in cos θ across the view).
  const overcastSun = await view(sun, sunView);
  const centre = 3 * (16 * 33 + 16);
  expect(luminance(overcastSun.brightest.value)).toBeLessThan(1.1 * luminance(overcastSun.mean));
  expect(Math.abs(luminance(overcastSun.pixels.slice(centre, centre + 3) as Vec3) / luminance(overcastSun.mean) - 1)).toBeLessThan(0.02);
  expect(errors).toEqual([]);
});

test('the sea’s glint dims with the cloud cover as the direct sun does (Kasten & Czeplak 1980), and is gone overcast', async ({ page }) => {
  const errors: string[] = [];
  page.on('pageerror', (error) => errors.push(error.message));
  await page.goto('/tests/browser/lighting/lighting.html');
  await expect(page).toHaveTitle('ready');
  // Looking down at the glitter of a sun 30° high from 200 m (as the lighting spec's Cox–Munk test),
  // in linear radiance: the glint is the picture less the same picture without the sun's light on
  // the water, summed over the picture.
  const request: ViewRequest = {
    windSpeed: 10,
    quality: 'high',
    width: 160,
    height: 120,
    eyeHeight: 200,
    pitch: 45,
    yaw: 0,
    fov: 100,
    sunElevation: 30,
    sunAzimuth: 0,
    time: 7,
    linear: true,
  };
  const glint = async (cloudCover: number): Promise<number> => {
    const lit = await page.evaluate((r) => window.lightingHarness.render(r), { ...request, cloudCover });
    const unlit = await page.evaluate((r) => window.lightingHarness.render(r), { ...request, cloudCover, sunlit: false });
    let sum = 0;
    for (let i = 1; i < lit.pixels.length; i += 4) sum += lit.pixels[i] - unlit.pixels[i];
    return sum;
  };
  const covers = [0, 0.5, 0.8, 1];
  const glints: number[] = [];
  for (const cover of covers) glints.push(await glint(cover));
  console.log(covers.map((c, i) => `cloudCover ${c}: glint ${(glints[i] / glints[0]).toFixed(4)} of the clear sky's (Kasten & Czeplak ${cloudSunTransmittance(c).toFixed(4)})`).join('\n'));
  expect(glints[0]).toBeGreaterThan(0);
  for (let i = 1; i < covers.length - 1; i++) expect(Math.abs(glints[i] / glints[0] - cloudSunTransmittance(covers[i]))).toBeLessThan(0.03);
  expect(Math.abs(glints[covers.length - 1])).toBeLessThan(1e-3 * glints[0]);

  // Pictures to look at: the glitter under a clear, a half-clouded and an overcast sky, as the app shows them.
  mkdirSync('test-results/clouds', { recursive: true });
  for (const cover of [0, 0.5, 1]) {
    const shot = await page.evaluate((r) => window.lightingHarness.render(r), { ...request, eyeHeight: 20, pitch: 4, fov: 60, width: 480, height: 270, linear: false, png: true, cloudCover: cover });
    writeFileSync(`test-results/clouds/cloud-cover-${cover}.png`, Buffer.from(shot.png!.split(',')[1], 'base64'));
  }
  expect(errors).toEqual([]);
});
