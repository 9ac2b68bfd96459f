/**
 * The local-wave model (src/layers/localWaveModel.ts): its JS solver against a naive DFT, and the
 * physics it must show against published laws: rings spreading at the group speed of their
 * wavelength, the Kelvin wedge behind a moving hull, and a border that absorbs.
 */
import { describe, expect, it } from 'vitest';
import {
  CpuLocalWaves,
  impulseHeight,
  localWaterUnder,
  signedIndex,
  spongeFactor,
  SPONGE_WIDTH_FRACTION,
  type HeightImpulse,
  type LocalWaveGrid,
  type LocalWaveStep,
  type LocalWaveWater,
} from '../../src/layers/localWaveModel';
import { angularFrequency, GRAVITY } from '../../src/spectrum/dispersion';

/** One step of the model written out with O(N⁴) sums instead of FFTs. */
function naiveStep(grid: LocalWaveGrid, height: Float64Array, potential: Float64Array, step: LocalWaveStep) {
  const n = grid.resolution;
  const eta = new Float64Array(n * n);
  const psi = new Float64Array(n * n);
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      const [fi, fj] = [i + step.shiftX, j + step.shiftZ];
      const inside = fi >= 0 && fi < n && fj >= 0 && fj < n;
      const damping = spongeFactor(i, j, grid, step.dt);
      eta[j * n + i] = inside ? height[fj * n + fi] * damping : 0;
      psi[j * n + i] = inside ? potential[fj * n + fi] * damping : 0;
      for (const impulse of step.impulses) eta[j * n + i] += impulseHeight(impulse, i * grid.cellSize, j * grid.cellSize);
    }
  }
  const dk = (2 * Math.PI) / (n * grid.cellSize);
  const out = { height: new Float64Array(n * n), potential: new Float64Array(n * n), slopeX: new Float64Array(n * n), slopeZ: new Float64Array(n * n) };
  // Z(k) = Σ (η + iψ)·e^{−ik·x}, rotated by e^{−iωΔt}.
  const zRe = new Float64Array(n * n);
  const zIm = new Float64Array(n * n);
  for (let q = 0; q < n; q++) {
    for (let p = 0; p < n; p++) {
      let re = 0;
      let im = 0;
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const angle = (-2 * Math.PI * (p * i + q * j)) / n;
          re += eta[j * n + i] * Math.cos(angle) - psi[j * n + i] * Math.sin(angle);
          im += eta[j * n + i] * Math.sin(angle) + psi[j * n + i] * Math.cos(angle);
        }
      }
      const phase = -angularFrequency(Math.hypot(signedIndex(p, n), signedIndex(q, n)) * dk, grid.depth) * step.dt;
      zRe[q * n + p] = re * Math.cos(phase) - im * Math.sin(phase);
      zIm[q * n + p] = re * Math.sin(phase) + im * Math.cos(phase);
    }
  }
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < n; i++) {
      for (let q = 0; q < n; q++) {
        for (let p = 0; p < n; p++) {
          const angle = (2 * Math.PI * (p * i + q * j)) / n;
          const [c, s] = [Math.cos(angle) / (n * n), Math.sin(angle) / (n * n)];
          const [re, im] = [zRe[q * n + p], zIm[q * n + p]];
          out.height[j * n + i] += re * c - im * s;
          out.potential[j * n + i] += re * s + im * c;
          // η = Re(η + iψ), so ∂η/∂x = Re(Σ i·kx·Z·e^{ik·x}) (no slope at the Nyquist frequency).
          const kx = p === n / 2 ? 0 : signedIndex(p, n) * dk;
          const kz = q === n / 2 ? 0 : signedIndex(q, n) * dk;
          out.slopeX[j * n + i] -= kx * (re * s + im * c);
          out.slopeZ[j * n + i] -= kz * (re * s + im * c);
        }
      }
    }
  }
  return out;
}

function maxAbs(a: ArrayLike<number>): number {
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i]));
  return m;
}

describe('the vertical velocity of the local waves', () => {
  it('is the time derivative of the height: IFFT(ω·FFT(ψ)) against a central difference over ±1 ms (within 0.1 %)', () => {
    const grid: LocalWaveGrid = { resolution: 64, cellSize: 1, depth: 6 };
    const solver = new CpuLocalWaves(grid);
    solver.step({ shiftX: 0, shiftZ: 0, impulses: [{ x: 30, z: 34, cos: 1, sin: 0, halfLength: 1.5, halfBeam: 1.5, height: -0.5 }], dt: 0 });
    for (let k = 0; k < 20; k++) solver.step({ shiftX: 0, shiftZ: 0, impulses: [], dt: 0.1 });
    const velocity = new Float32Array(4 * 64 * 64);
    solver.verticalVelocity(solver.potential, 1, velocity);
    // A step of the model is exact: one of −1 ms and one of +1 ms from the same state.
    const state = [Float64Array.from(solver.height), Float64Array.from(solver.potential)];
    const heightAfter = (dt: number) => {
      solver.height.set(state[0]);
      solver.potential.set(state[1]);
      solver.step({ shiftX: 0, shiftZ: 0, impulses: [], dt });
      return Float64Array.from(solver.height);
    };
    const [later, earlier] = [heightAfter(1e-3), heightAfter(-1e-3)];
    let worst = 0;
    let largest = 0;
    // Inside the sponge (8 texels wide here) a step also damps, which is no motion of the water.
    for (let j = 8; j < 56; j++) {
      for (let i = 8; i < 56; i++) {
        const t = j * 64 + i;
        const expected = (later[t] - earlier[t]) / 2e-3;
        largest = Math.max(largest, Math.abs(expected));
        worst = Math.max(worst, Math.abs(velocity[4 * t + 1] - expected));
      }
    }
    expect(largest).toBeGreaterThan(0.01);
    expect(worst / largest).toBeLessThan(1e-3);
  });
});

describe('the JS solver against a naive DFT', () => {
  it('takes the same step (shift, sponge, sources, exact rotation, slopes) to 1e-12', () => {
    const grid: LocalWaveGrid = { resolution: 16, cellSize: 0.5, depth: 3 };
    const solver = new CpuLocalWaves(grid);
    const drop: HeightImpulse = { x: 3.2, z: 4.1, cos: 0.8, sin: 0.6, halfLength: 1.1, halfBeam: 0.6, height: -0.4 };
    solver.step({ shiftX: 0, shiftZ: 0, impulses: [drop], dt: 0.3 });
    const height = Float64Array.from(solver.height);
    const potential = Float64Array.from(solver.potential);
    const step: LocalWaveStep = { shiftX: 1, shiftZ: -2, impulses: [{ ...drop, x: 4, height: 0.2 }], dt: 0.45 };
    solver.step(step);
    const expected = naiveStep(grid, height, potential, step);
    const scale = maxAbs(expected.height);
    expect(scale).toBeGreaterThan(0.01);
    for (const key of ['height', 'potential', 'slopeX', 'slopeZ'] as const) {
      for (let t = 0; t < 256; t++) expect(Math.abs(solver[key][t] - expected[key][t])).toBeLessThan(1e-12 * Math.max(1, scale));
    }
  });
});

/** Bilinear sample of a field on the grid at (x, z) metres from texel (0, 0). */
function sampleAt(field: Float64Array, grid: LocalWaveGrid, x: number, z: number): number {
  const n = grid.resolution;
  const [u, v] = [x / grid.cellSize, z / grid.cellSize];
  const [i, j] = [Math.floor(u), Math.floor(v)];
  const [fu, fv] = [u - i, v - j];
  const at = (a: number, b: number) => field[b * n + a];
  return (1 - fv) * ((1 - fu) * at(i, j) + fu * at(i + 1, j)) + fv * ((1 - fu) * at(i, j + 1) + fu * at(i + 1, j + 1));
}

/** The ring's profile η(r) around (cx, cz), averaged over 16 directions, r in steps of dr up to rMax. */
function radialProfile(field: Float64Array, grid: LocalWaveGrid, cx: number, cz: number, dr: number, rMax: number): number[] {
  const profile: number[] = [];
  for (let r = 0; r <= rMax; r += dr) {
    let sum = 0;
    for (let a = 0; a < 16; a++) sum += sampleAt(field, grid, cx + r * Math.cos((a * Math.PI) / 8), cz + r * Math.sin((a * Math.PI) / 8));
    profile.push(sum / 16);
  }
  return profile;
}

/** Radii of the crests (local maxima, placed by a parabola through three samples) above `floor`. */
function crestRadii(profile: number[], dr: number, floor: number): number[] {
  const crests: number[] = [];
  for (let s = 1; s + 1 < profile.length; s++) {
    const [a, b, c] = [profile[s - 1], profile[s], profile[s + 1]];
    if (b > a && b >= c && b > floor) crests.push((s + (0.5 * (a - c)) / (a - 2 * b + c)) * dr);
  }
  return crests;
}

/** The zero crossings of the profile just inside and just outside the radius `r`, interpolated linearly. */
function zeroCrossingsAround(profile: number[], dr: number, r: number): [number, number] {
  const s = Math.round(r / dr);
  const crossing = (from: number, direction: number) => {
    for (let a = from; a + direction >= 0 && a + direction < profile.length; a += direction) {
      const [p, q] = [profile[a], profile[a + direction]];
      if (Math.sign(p) !== Math.sign(q)) return (a + (direction * p) / (p - q)) * dr;
    }
    return NaN;
  };
  return [crossing(s, -1), crossing(s, 1)];
}

describe('the physics of local waves', () => {
  // Deep-water dispersion ω² = g·k (Airy; Lamb, "Hydrodynamics", §228): phase speed √(g/k) and group
  // speed half of it.
  const phaseSpeed = (k: number) => Math.sqrt(GRAVITY / k);
  const groupSpeed = (k: number) => 0.5 * phaseSpeed(k);

  it('spreads a stone\'s rings at the group speed of their local wavelength, crests at the phase speed (within 5 %)', () => {
    // Cauchy–Poisson problem: at radius r and time t the waves have the wavenumber whose group speed is
    // r/t (stationary phase: Lighthill, "Waves in Fluids" (1978), §3.6; Whitham (1974), §11.4), and each
    // crest moves at the phase speed of that wavenumber.
    const grid: LocalWaveGrid = { resolution: 512, cellSize: 0.25, depth: Infinity };
    const solver = new CpuLocalWaves(grid);
    const centre = 64;
    const stone: HeightImpulse = { x: centre, z: centre, cos: 1, sin: 0, halfLength: 0.4, halfBeam: 0.4, height: -0.2 };
    const dt = 0.1;
    const t1 = 12;
    // Crests are followed from t1 − h to t1 + h: a crest's radius grows as t² (its phase g·t²/4r stays
    // fixed), so the central difference is its speed at t1.
    const h = 0.5;
    const dr = 0.05;
    const advance = (seconds: number) => {
      for (let t = 0; t < seconds - 1e-9; t += dt) solver.step({ shiftX: 0, shiftZ: 0, impulses: [], dt });
    };
    solver.step({ shiftX: 0, shiftZ: 0, impulses: [stone], dt: 0 });
    advance(t1 - h);
    const earlier = radialProfile(solver.height, grid, centre, centre, dr, 40);
    advance(h);
    const before = radialProfile(solver.height, grid, centre, centre, dr, 40);
    advance(h);
    const after = radialProfile(solver.height, grid, centre, centre, dr, 40);
    const peak = maxAbs(before.slice(Math.round(3 / dr)));
    const crests = crestRadii(before, dr, 0.2 * peak).filter((r) => r > 3);
    const [previous, later] = [crestRadii(earlier, dr, 0.1 * peak), crestRadii(after, dr, 0.1 * peak)];
    const nearest = (radii: number[], r: number) => radii.reduce((best, q) => (Math.abs(q - r) < Math.abs(best - r) ? q : best));
    const groupRatios: number[] = [];
    const phaseRatios: number[] = [];
    for (const crest of crests) {
      // The local wavelength: twice the distance between the zero crossings on either side of the crest.
      const [inner, outer] = zeroCrossingsAround(before, dr, crest);
      const k = Math.PI / (outer - inner);
      // Stationary phase is the leading term of an expansion in 1/(k·r), and a profile sampled
      // bilinearly places crests well only with several texels per wavelength: measure where both hold.
      if (k * crest < 20 || (2 * Math.PI) / k < 5 * grid.cellSize) continue;
      groupRatios.push(crest / t1 / groupSpeed(k));
      const move = phaseSpeed(k) * h;
      phaseRatios.push((nearest(later, crest + move) - nearest(previous, crest - move)) / (2 * move));
    }
    console.log('ring at t = ' + t1 + ' s: crest radii (m)', crests.map((r) => r.toFixed(2)).join(' '), '| (r/t) ÷ c_g', groupRatios.map((r) => r.toFixed(3)).join(' '), '| crest speed ÷ c_p', phaseRatios.map((r) => r.toFixed(3)).join(' '));
    expect(groupRatios.length).toBeGreaterThanOrEqual(3);
    for (const ratio of [...groupRatios, ...phaseRatios]) expect(Math.abs(ratio - 1)).toBeLessThan(0.05);
  });

  it('draws a Kelvin wedge of half-angle 19.47° ± 2° behind a hull in steady motion', () => {
    // Kelvin (1887): in deep water the waves of a source moving steadily stay inside a wedge of
    // half-angle asin(1/3) = 19.47°, whatever its speed, and are largest along its edges (the cusp
    // lines). That holds for hulls short against the wavelength 2πU²/g: for Froude numbers U/√(g·L)
    // above ~0.5 the largest waves move inside the wedge (Rabaud & Moisy 2013, "Ship wakes: Kelvin or
    // Mach angle?", Phys. Rev. Lett. 110, 214503). Here U/√(g·L) = 0.4.
    const grid: LocalWaveGrid = { resolution: 256, cellSize: 0.5, depth: Infinity };
    const solver = new CpuLocalWaves(grid);
    const speed = 2.5;
    const hull = { halfLength: 2, halfBeam: 0.8, draft: 0.3 };
    expect(speed / Math.sqrt(GRAVITY * 2 * hull.halfLength)).toBeCloseTo(0.4, 1);
    const dt = 0.1;
    // The grid follows the hull, which stays near (96 m, 64 m) of it: 80 m of wake behind.
    const hullInGrid = { x: 96, z: 64 };
    let hullX = 0;
    let originTexel = Math.floor((hullX - hullInGrid.x) / grid.cellSize);
    const pressure = (x: number, height: number): HeightImpulse => ({
      x: x - originTexel * grid.cellSize,
      z: hullInGrid.z,
      cos: 1,
      sin: 0,
      halfLength: hull.halfLength,
      halfBeam: hull.halfBeam,
      height,
    });
    solver.step({ shiftX: 0, shiftZ: 0, impulses: [pressure(hullX, hull.draft)], dt: 0 });
    for (let t = 0; t < 40; t += dt) {
      const previousX = hullX;
      hullX += speed * dt;
      const nextOrigin = Math.floor((hullX - hullInGrid.x) / grid.cellSize);
      const shift = nextOrigin - originTexel;
      originTexel = nextOrigin;
      solver.step({ shiftX: shift, shiftZ: 0, impulses: [pressure(hullX, hull.draft), pressure(previousX, -hull.draft)], dt });
    }
    // Along each cross-section behind the hull, where the waves are largest: the envelope |η| taken
    // as the largest over a wavelength along the track.
    const n = grid.resolution;
    const hullTexel = (hullX - originTexel * grid.cellSize) / grid.cellSize;
    const wavelengthTexels = Math.round((2 * Math.PI * speed * speed) / GRAVITY / grid.cellSize);
    const behind: number[] = [];
    const lateral: number[] = [];
    for (let back = 24; back <= 110; back += 2) {
      const column = Math.round(hullTexel - back);
      for (const side of [1, -1]) {
        let best = 0;
        let bestOffset = 0;
        for (let offset = 2; offset < 90; offset++) {
          const row = 128 + side * offset;
          let envelope = 0;
          for (let c = column - wavelengthTexels / 2; c <= column + wavelengthTexels / 2; c++) envelope = Math.max(envelope, Math.abs(solver.height[row * n + c]));
          if (envelope > best) [best, bestOffset] = [envelope, offset];
        }
        behind.push((hullTexel - column) * grid.cellSize);
        lateral.push(bestOffset * grid.cellSize);
      }
    }
    // Least-squares line lateral = a + b·behind: the cusp lines leave from near the hull.
    const mean = (values: number[]) => values.reduce((sum, v) => sum + v, 0) / values.length;
    const [mx, my] = [mean(behind), mean(lateral)];
    let sxy = 0;
    let sxx = 0;
    behind.forEach((x, i) => {
      sxy += (x - mx) * (lateral[i] - my);
      sxx += (x - mx) * (x - mx);
    });
    const halfAngle = (Math.atan(sxy / sxx) * 180) / Math.PI;
    console.log(`Kelvin wake: half-angle ${halfAngle.toFixed(2)}° (Kelvin: 19.47°), from ${behind.length} cross-sections ${behind[0]}–${behind[behind.length - 1]} m behind`);
    expect(Math.abs(halfAngle - (Math.asin(1 / 3) * 180) / Math.PI)).toBeLessThan(2);
  });

  it.each([2, 4, 8, 16])('absorbs at the border: of a %s m wave packet, under 5 percent of the energy comes back', (wavelength) => {
    // A packet travelling +x, one-sided in k (so it travels one way): Z(k) a Gaussian around
    // (2π/λ, 0), centred on the grid. Its energy is ρg/2·Σ(η² + ψ²) (potential plus kinetic, by
    // Parseval, linear theory: Lamb, "Hydrodynamics", §230). Once the packet has gone into the sponge,
    // whatever is found again inside it came back: reflected, or through the sponge and round the
    // periodic grid.
    const grid: LocalWaveGrid = { resolution: 256, cellSize: 0.5, depth: Infinity };
    const n = grid.resolution;
    const solver = new CpuLocalWaves(grid);
    const k0 = (2 * Math.PI) / wavelength;
    const width = Math.min(2 * wavelength, 12); // the envelope's standard deviation, m (3 of them fit inside)
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const [x, z] = [(i - n / 2) * grid.cellSize, (j - n / 2) * grid.cellSize];
        const envelope = 0.1 * Math.exp(-(x * x + z * z) / (2 * width * width));
        solver.height[j * n + i] = envelope * Math.cos(k0 * x);
        solver.potential[j * n + i] = envelope * Math.sin(k0 * x);
      }
    }
    const sponge = n * SPONGE_WIDTH_FRACTION;
    const interiorEnergy = () => {
      let sum = 0;
      for (let j = sponge; j < n - sponge; j++) for (let i = sponge; i < n - sponge; i++) sum += solver.height[j * n + i] ** 2 + solver.potential[j * n + i] ** 2;
      return sum;
    };
    const initial = interiorEnergy();
    // The packet's back leaves the interior after (distance to the sponge + 3 widths) / group speed.
    const group = 0.5 * Math.sqrt(GRAVITY / k0);
    const gone = ((n / 2 - sponge) * grid.cellSize + 3 * width) / group;
    const dt = 0.5;
    let returned = 0;
    for (let t = 0; t < 2.5 * gone; t += dt) {
      solver.step({ shiftX: 0, shiftZ: 0, impulses: [], dt });
      if (t > gone) returned = Math.max(returned, interiorEnergy() / initial);
    }
    console.log(`border: ${wavelength} m packet, ${(100 * returned).toFixed(2)} % of its energy back inside`);
    expect(returned).toBeLessThan(0.05);
  });
});

describe('local waves over a seabed', () => {
  // Airy's dispersion over a flat bottom of depth d, ω² = g·k·tanh(k·d) (Dean & Dalrymple 1991,
  // "Water Wave Mechanics for Engineers and Scientists", eq. 3.34), with group speed
  // c_g = ½·(1 + 2kd/sinh 2kd)·ω/k (eq. 4.55 there); in shallow water (kd → 0) every wave moves at
  // √(g·d), the fastest any wave moves at that depth (eq. 3.37).
  const groupSpeed = (k: number, d: number) => (d === Infinity ? 0.5 : 0.5 * (1 + (2 * k * d) / Math.sinh(2 * k * d))) * (angularFrequency(k, d) / k);
  const grid: LocalWaveGrid = { resolution: 512, cellSize: 0.5, depth: Infinity };
  const centre = (grid.resolution / 2) * grid.cellSize;
  /** Bounds that take in the whole plane, and the mask localWaterUnder fills. */
  const everywhere = [-Infinity, -Infinity, Infinity, Infinity] as const;
  const mask = new Float32Array(grid.resolution * grid.resolution);
  /** A flat bottom `depth` m deep under the whole grid: the water localWaterUnder finds there. */
  const flat = (depth: number) => localWaterUnder(grid, 0, 0, { depthAt: () => depth, bounds: everywhere }, Infinity, mask);

  /** A stone (radius `radius` m) at the grid's centre over `water`, stepped exactly to each time in `times`: the radial profiles. */
  function rings(water: LocalWaveWater, radius: number, times: number[]): number[][] {
    const solver = new CpuLocalWaves(grid);
    solver.setWater(water);
    solver.step({ shiftX: 0, shiftZ: 0, impulses: [{ x: centre, z: centre, cos: 1, sin: 0, halfLength: radius, halfBeam: radius, height: -0.2 }], dt: 0 });
    let now = 0;
    return times.map((t) => {
      // The step is exact for any Δt (e^{−iωΔt} per mode): one step to each time.
      solver.step({ shiftX: 0, shiftZ: 0, impulses: [], dt: t - now });
      now = t;
      return radialProfile(solver.height, grid, centre, centre, 0.05, 120);
    });
  }

  it('finds the depth of the water under the grid and its land', () => {
    expect(flat(2)).toEqual({ depth: 2, wet: null });
    // Deeper than the grid is wide (256 m) everywhere: every mode is in deep water.
    expect(flat(300).depth).toBe(Infinity);
    // A beach along x: land for x < 40 m, then 1:20.
    const beach = localWaterUnder(grid, 0, 0, { depthAt: (x) => (x - 40) / 20, bounds: everywhere }, 30, mask);
    const landTexels = Math.ceil(40 / grid.cellSize) + 1; // x = 0 … 40 m: depth ≤ 0
    expect(beach.wet![landTexels - 1]).toBe(0);
    expect(beach.wet![landTexels]).toBe(1);
    // The wet texels' mean depth: (0.5 + 1 + … + 216 m)/20 over 432 columns.
    const columns = Array.from({ length: grid.resolution - landTexels }, (_, c) => (landTexels + c) * grid.cellSize);
    expect(beach.depth).toBeCloseTo(columns.reduce((sum, x) => sum + (x - 40) / 20, 0) / columns.length, 9);
    // All land: the open depth kept, nothing wet.
    const island = localWaterUnder(grid, 0, 0, { depthAt: () => -1, bounds: everywhere }, 30, mask);
    expect(island.depth).toBe(30);
    expect(island.wet!.every((w) => w === 0)).toBe(true);
  });

  it('reads the seabed only within its bounds, the rest open water: the same water as a read of every texel, in the mask it is given', () => {
    // A mound with land at its top, in a 120 × 110 m rectangle that covers part of the grid (256 m
    // a side, its texel (0, 0) at x = −20 m, z = 30 m); 12 m deep beyond the rectangle.
    const bounds = [10, 40, 130, 150] as const;
    const inside = (x: number, z: number) => x >= bounds[0] && x <= bounds[2] && z >= bounds[1] && z <= bounds[3];
    const mound = (x: number, z: number) => 8 - 10 * Math.exp(-(((x - 70) / 30) ** 2) - ((z - 95) / 30) ** 2);
    let reads = 0;
    const seabed = {
      bounds,
      depthAt: (x: number, z: number, outside: number) => {
        reads++;
        return inside(x, z) ? mound(x, z) : outside;
      },
    };
    const everyTexel = localWaterUnder(grid, -20, 30, { bounds: everywhere, depthAt: (x, z) => (inside(x, z) ? mound(x, z) : 12) }, 12, new Float32Array(mask.length));
    const read = localWaterUnder(grid, -20, 30, seabed, 12, mask);
    expect(read.wet).toBe(mask);
    expect(Array.from(read.wet!)).toEqual(Array.from(everyTexel.wet!));
    expect(read.depth).toBeCloseTo(everyTexel.depth, 9);
    expect(read.wet!.some((w) => w === 0)).toBe(true);
    // The rectangle's 241 × 221 texels (0.5 m apart) and one more round them, not the grid's 512².
    expect(reads).toBe(243 * 223);
    // The mask is filled again, not added to: out at sea, all wet and none of it land.
    expect(localWaterUnder(grid, 1000, 1000, seabed, 12, mask)).toEqual({ depth: 12, wet: null });
    expect(mask.every((w) => w === 1)).toBe(true);
  });

  it('in 2 m of water a stone\'s disturbance spreads at the shallow-water speed √(g·d) (within 10 %)', () => {
    // The front of the disturbance carries the longest waves, which move at √(g·d); its Airy-function
    // shape widens as t^⅓ (Whitham 1974, §13.7), so its speed is measured between two late times.
    const d = 2;
    const times = [8, 16];
    const profiles = rings(flat(d), 2, times);
    const fronts = profiles.map((profile) => {
      const peak = maxAbs(profile.slice(Math.round(10 / 0.05)));
      let r = profile.length - 1;
      while (Math.abs(profile[r]) < 0.2 * peak) r--;
      return r * 0.05;
    });
    const speed = (fronts[1] - fronts[0]) / (times[1] - times[0]);
    console.log(`2 m of water: front at ${fronts.map((r) => r.toFixed(2)).join(', ')} m at t = ${times.join(', ')} s: ${speed.toFixed(3)} m/s against √(g·d) = ${Math.sqrt(GRAVITY * d).toFixed(3)} m/s`);
    expect(Math.abs(speed / Math.sqrt(GRAVITY * d) - 1)).toBeLessThan(0.1);
  });

  it.each([2, 300])('over a %s m bottom the rings\' crests lie where the group speed of their wavelength takes them (within 5 %)', (d) => {
    // Stationary phase (Lighthill 1978, §3.6): at radius r and time t the waves have the wavenumber
    // whose group speed at this depth is r/t (in deep water c_g = ½·√(g/k), the ring test above).
    const t = 20;
    const [profile] = rings(flat(d), 1, [t]);
    const water = flat(d);
    const peak = maxAbs(profile.slice(Math.round(3 / 0.05)));
    const ratios: number[] = [];
    for (const crest of crestRadii(profile, 0.05, 0.1 * peak).filter((r) => r > 3)) {
      const [inner, outer] = zeroCrossingsAround(profile, 0.05, crest);
      const k = Math.PI / (outer - inner);
      if (k * crest < 20 || (2 * Math.PI) / k < 5 * grid.cellSize) continue;
      ratios.push(crest / t / groupSpeed(k, water.depth));
    }
    console.log(`${d} m bottom (dispersion depth ${water.depth}): (r/t) ÷ c_g(k, d) at t = ${t} s:`, ratios.map((r) => r.toFixed(3)).join(' '));
    expect(ratios.length).toBeGreaterThanOrEqual(3);
    for (const ratio of ratios) expect(Math.abs(ratio - 1)).toBeLessThan(0.05);
  });

  it('over land nothing moves: a stone dropped by a beach leaves the sand flat, the water beside it waving', () => {
    const small: LocalWaveGrid = { resolution: 128, cellSize: 0.5, depth: Infinity };
    // Land for x < 20 m, then a 1:20 beach.
    const water = localWaterUnder(small, 0, 0, { depthAt: (x) => (x - 20) / 20, bounds: everywhere }, Infinity, new Float32Array(128 * 128));
    const solver = new CpuLocalWaves(small);
    solver.setWater(water);
    solver.step({ shiftX: 0, shiftZ: 0, impulses: [{ x: 26, z: 32, cos: 1, sin: 0, halfLength: 1, halfBeam: 1, height: -0.3 }], dt: 0 });
    let onLand = 0;
    let inWater = 0;
    for (let s = 0; s < 40; s++) {
      solver.step({ shiftX: 0, shiftZ: 0, impulses: [], dt: 0.25 });
      for (let at = 0; at < water.wet!.length; at++) {
        const moved = Math.max(Math.abs(solver.height[at]), Math.abs(solver.potential[at]), Math.abs(solver.slopeX[at]), Math.abs(solver.slopeZ[at]));
        if (water.wet![at] === 0) onLand = Math.max(onLand, moved);
        else inWater = Math.max(inWater, Math.abs(solver.height[at]));
      }
    }
    expect(inWater).toBeGreaterThan(0.01);
    expect(onLand).toBe(0);
  });
});
