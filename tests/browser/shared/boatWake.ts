import type { Page } from '@playwright/test';

/**
 * The boat of the app (`'app'`) or of the first <fft-ocean> (`'element'`) and its wake: the
 * largest height of the local waves within 3 m of points 12 m astern and 25 m ahead of it (a
 * Kelvin wake lies behind a boat, calm water ahead), the largest coverage of its foam
 * (src/layers/hullFoam.ts) within 3 m of the same points, and how far it is from where its course
 * puts it now (m).
 */
export function boatWake(page: Page, source: 'app' | 'element'): Promise<{ astern: number; ahead: number; foamAstern: number; foamAhead: number; onCourse: number }> {
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
    const foam = waves.foam.coverage;
    const largestNear = (dx: number, dz: number, field: (texel: number) => number) => {
      let largest = 0;
      for (let r = -3; r <= 3; r++) {
        for (let c = -3; c <= 3; c++) {
          const i = Math.round(((x + dx + c - origin[0]) / size) * resolution);
          const j = Math.round(((z + dz + r - origin[1]) / size) * resolution);
          largest = Math.max(largest, Math.abs(field(j * resolution + i)));
        }
      }
      return largest;
    };
    const [cos, sin] = [Math.cos(pose.heading), Math.sin(pose.heading)];
    const height = (texel: number) => displacement[4 * texel + 1];
    const coverage = (texel: number) => foam[texel];
    return {
      astern: largestNear(-12 * cos, -12 * sin, height),
      ahead: largestNear(25 * cos, 25 * sin, height),
      foamAstern: largestNear(-12 * cos, -12 * sin, coverage),
      foamAhead: largestNear(25 * cos, 25 * sin, coverage),
      onCourse: Math.hypot(pose.x - x, pose.z - z),
    };
  }, source);
}
