// Writes the six face PNGs of a sky box, public/skybox/<name>/{px,nx,py,ny,pz,nz}.png, by
// evaluating the analytic sky in JS: nothing is downloaded. `npm run make-skybox` makes the
// shipped set; `node scripts/make-skybox-faces.mjs [name] [elevationDeg] [azimuthDeg] [size]`
// makes others.
//
// skyRadiance() below is a port of shaders/sky/analyticSky.glsl (the formulas and their sources
// are described there): keep the two in step. tests/browser/sky/sky.spec.ts loads the shipped set
// and compares it with the shader in many directions, which also checks the face orientation.
// If you change the shipped set's sun, change SHIPPED_SKYBOX in src/render/skyEnvironment.ts.
//
// Face layout: three.js's CubeTextureLoader uploads each image as one face of a GL cube map
// (px, nx, py, ny, pz, nz; first image row = t 0, no flip), so the texel at (s, t) of face +X is
// the GL direction (1, −(2t−1), −(2s−1)) (OpenGL 4.6 §8.13 table 8.19) and likewise for the
// others. three.js samples image cube maps with x mirrored (their left-handed convention), so
// that texel shows the world direction (−1, −(2t−1), −(2s−1)).
//
// The PNGs are 8-bit sRGB, so the HDR radiance is tone-mapped: identity up to KNEE (which keeps
// the sky itself equal to the generated cube) and a smooth exponential shoulder above it (the
// sun, the brightest haze) that approaches 1.
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const [name = 'clear-afternoon', elevationArg = '30', azimuthArg = '40', sizeArg = '256'] = process.argv.slice(2);
const sunElevation = Number(elevationArg);
const sunAzimuth = Number(azimuthArg);
const size = Number(sizeArg);
if (!/^[a-z0-9-]+$/.test(name)) throw new Error(`name must be lower-case letters, digits and dashes, got ${name}`);
if (!Number.isFinite(sunElevation) || sunElevation < -90 || sunElevation > 90) {
  throw new Error(`elevation must be degrees in [-90, 90], got ${elevationArg}`);
}
if (!Number.isFinite(sunAzimuth)) throw new Error(`azimuth must be a number of degrees, got ${azimuthArg}`);
if (!Number.isInteger(size) || size < 1 || size > 4096) throw new Error(`size must be an integer in [1, 4096], got ${sizeArg}`);

// ---- The uniforms SkyEnvironment gives the shader by default.
const sunDirection = [
  Math.cos((sunElevation * Math.PI) / 180) * Math.cos((sunAzimuth * Math.PI) / 180),
  Math.sin((sunElevation * Math.PI) / 180),
  Math.cos((sunElevation * Math.PI) / 180) * Math.sin((sunAzimuth * Math.PI) / 180),
];
const sunColor = [1, 1, 1];
const sunIntensity = 16;
// skyDaylight of src/render/daylight.ts (a port: keep in step): the sky's light through twilight.
const daylight = Math.max(10 ** ((Math.log10(400 / 3.4) / 6) * Math.min(sunElevation, 0)), 0.002 / 400);
const deepWaterColor = [0.004, 0.01, 0.035].map((c) => c * daylight);

// ---- Port of shaders/sky/analyticSky.glsl.
const RAYLEIGH_DEPTH = [0.0464, 0.108, 0.2648];
const MIE_DEPTH = 0.021;
const MIE_G = 0.8;
const OZONE_DEPTH = [0.00975, 0.0282, 0.00128];
const SUN_RADIUS = 0.00698;
const SUN_EDGE = 0.00175;
const SUN_DISK_GAIN = 40;
const HORIZON_BLEND = 0.0698;

const clamp = (x, lo, hi) => Math.min(Math.max(x, lo), hi);
const smoothstep = (e0, e1, x) => {
  const t = clamp((x - e0) / (e1 - e0), 0, 1);
  return t * t * (3 - 2 * t);
};

function airMass(sinElevation) {
  const s = clamp(sinElevation, 0, 1);
  const elevationDegrees = (Math.asin(s) * 180) / Math.PI;
  return 1 / (s + 0.50572 * Math.pow(elevationDegrees + 6.07995, -1.6364));
}

/** Linear RGB radiance towards the unit world direction d (y up). */
function skyRadiance(d) {
  const sun = sunDirection;
  const sunAirMass = airMass(sun[1]);
  const viewAirMass = airMass(d[1]);
  const gamma = 2 * Math.asin(clamp(0.5 * Math.hypot(d[0] - sun[0], d[1] - sun[1], d[2] - sun[2]), 0, 1));
  const cosGamma = Math.cos(gamma);
  const rayleighPhase = (3 / (16 * Math.PI)) * (1 + cosGamma * cosGamma);
  const g2 = MIE_G * MIE_G;
  const miePhase = (1 - g2) / (4 * Math.PI * Math.pow(1 + g2 - 2 * MIE_G * cosGamma, 1.5));

  const r = Math.min(gamma / SUN_RADIUS, 1);
  const limb = 1 - 0.6 * (1 - Math.sqrt(1 - r * r));
  const disk = (1 - smoothstep(SUN_RADIUS - SUN_EDGE, SUN_RADIUS + SUN_EDGE, gamma)) * limb * smoothstep(-SUN_EDGE, SUN_EDGE, d[1]);
  const water = smoothstep(-HORIZON_BLEND, 0, d[1]);

  return [0, 1, 2].map((c) => {
    const depth = RAYLEIGH_DEPTH[c] + MIE_DEPTH + OZONE_DEPTH[c];
    const sunIrradiance = sunColor[c] * sunIntensity * daylight;
    const sunDepth = depth * sunAirMass;
    const direct = Math.exp(-sunDepth);
    const scatteredTransmittance = (1 - direct) / sunDepth;
    const scattering = (RAYLEIGH_DEPTH[c] * rayleighPhase + MIE_DEPTH * miePhase) / depth;
    const sky =
      sunIrradiance * scatteredTransmittance * scattering * (1 - Math.exp(-depth * viewAirMass)) +
      SUN_DISK_GAIN * disk * sunIrradiance * direct;
    if (water <= 0) return deepWaterColor[c];
    if (water >= 1) return sky;
    const darkest = 1e-6;
    return Math.exp((1 - water) * Math.log(Math.max(deepWaterColor[c], darkest)) + water * Math.log(Math.max(sky, darkest)));
  });
}

// ---- Tone mapping and encoding.
const KNEE = 0.8;
const toneMap = (x) => (x <= KNEE ? x : KNEE + (1 - KNEE) * (1 - Math.exp(-(x - KNEE) / (1 - KNEE))));
const srgb = (x) => (x <= 0.0031308 ? 12.92 * x : 1.055 * Math.pow(x, 1 / 2.4) - 0.055);
const toByte = (x) => Math.round(255 * clamp(srgb(toneMap(Math.max(x, 0))), 0, 1));

// GL cube-map direction of face coordinates sc, tc in [−1, 1] (table 8.19 inverted).
const FACES = {
  px: (sc, tc) => [1, -tc, -sc],
  nx: (sc, tc) => [-1, -tc, sc],
  py: (sc, tc) => [sc, 1, tc],
  ny: (sc, tc) => [sc, -1, -tc],
  pz: (sc, tc) => [sc, -tc, 1],
  nz: (sc, tc) => [-sc, -tc, -1],
};

const SUBSAMPLES = 3; // per axis: a 3×3 box filter keeps the 2-texel sun disk round
const outputDirectory = join(root, 'public', 'skybox', name);
mkdirSync(outputDirectory, { recursive: true });
for (const [face, glDirection] of Object.entries(FACES)) {
  const png = new PNG({ width: size, height: size, colorType: 2 });
  for (let row = 0; row < size; row++) {
    for (let column = 0; column < size; column++) {
      const sum = [0, 0, 0];
      for (let j = 0; j < SUBSAMPLES; j++) {
        for (let i = 0; i < SUBSAMPLES; i++) {
          const sc = (2 * (column + (i + 0.5) / SUBSAMPLES)) / size - 1;
          const tc = (2 * (row + (j + 0.5) / SUBSAMPLES)) / size - 1;
          const [x, y, z] = glDirection(sc, tc);
          const length = Math.hypot(x, y, z);
          const radiance = skyRadiance([-x / length, y / length, z / length]); // three.js mirrors x
          for (let c = 0; c < 3; c++) sum[c] += radiance[c];
        }
      }
      const index = 4 * (row * size + column);
      for (let c = 0; c < 3; c++) png.data[index + c] = toByte(sum[c] / SUBSAMPLES ** 2);
      png.data[index + 3] = 255;
    }
  }
  writeFileSync(join(outputDirectory, `${face}.png`), PNG.sync.write(png, { colorType: 2 }));
}
console.log(
  `Wrote ${Object.keys(FACES).length} faces of ${size}×${size} to ${outputDirectory} (sun at elevation ${sunElevation}°, azimuth ${sunAzimuth}°)`,
);
