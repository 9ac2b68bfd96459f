import type { Page } from '@playwright/test';

/**
 * The boat of the app (`'app'`) or of the first <fft-ocean> (`'element'`) and its wake: the
 * largest height of the local waves within 3 m of points 12 m astern and 25 m ahead of it (a
 * Kelvin wake lies behind a boat, calm water ahead), and how far it is from where its course puts
 * it now (m).
 */
export function boatWake(page: Page, source: 'app' | 'element'): Promise<{ astern: number; ahead: number; onCourse: number }> {
  return page.evaluate((source) => {
    const element = document.querySelector('fft-ocean');
    const ocean = source === 'app' ? window.oceanApp.ocean : element!.ocean!;
    const boat = source === 'app' ? window.oceanApp.boat! : (element!.scene!.getObjectByName('boat') as typeof window.oceanApp.boat)!;
    const t = ocean.time;
    const { x, z } = boat.position;
    const pose = boat.poseAt(t);
    const waves = ocean.localWaves!;
    const { size, origin, resolution } = waves.frame;
    const { displacement } = waves.fieldsOnCpu(t);
    const largestNear = (dx: number, dz: number) => {
      let largest = 0;
      for (let r = -3; r <= 3; r++) {
        for (let c = -3; c <= 3; c++) {
          const i = Math.round(((x + dx + c - origin[0]) / size) * resolution);
          const j = Math.round(((z + dz + r - origin[1]) / size) * resolution);
          largest = Math.max(largest, Math.abs(displacement[4 * (j * resolution + i) + 1]));
        }
      }
      return largest;
    };
    const [cos, sin] = [Math.cos(pose.heading), Math.sin(pose.heading)];
    return { astern: largestNear(-12 * cos, -12 * sin), ahead: largestNear(25 * cos, 25 * sin), onCourse: Math.hypot(pose.x - x, pose.z - z) };
  }, source);
}
