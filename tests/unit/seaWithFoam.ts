/**
 * A sea's cascades in JS with the whitecap foam over its largest patch, advanced as whitecapFoam.ts
 * and OceanSimulation do (the calibration is OceanSimulation.foamCalibration's): for the foam tests.
 */
import { CpuWaveFields } from '../../src/fft/cpuWaveFields';
import { calibrateFoam, CpuFoamField, foamCreationRate, foamSchedule, jacobianCovariance } from '../../src/layers/foamModel';
import { validateParameters, type SimulationParameters } from '../../src/parameters/parameters';
import { createCascadeSpectra } from '../../src/spectrum/initialSpectrum';

/** The sea's cascades in JS and the foam over its largest patch, advanced as whitecapFoam.ts does. */
export function seaWithFoam(parameters: Partial<SimulationParameters>) {
  const p = validateParameters(parameters);
  const spectra = createCascadeSpectra(p);
  const cascades = spectra.map((spectrum) => ({ fields: new CpuWaveFields(spectrum), size: spectrum.patchSize, resolution: spectrum.resolution }));
  const largest = spectra[spectra.length - 1];
  const foam = new CpuFoamField(largest.patchSize, largest.resolution);
  // What OceanSimulation.foamCalibration gives.
  const calibration = calibrateFoam(jacobianCovariance(spectra), p.choppiness, p.windSpeed);
  let lastTime = NaN;
  return {
    foam,
    calibration,
    advance(t: number): void {
      const { clear, steps } = foamSchedule(lastTime, t, p.foamPersistence);
      lastTime = t;
      if (clear) foam.clear();
      for (const { time, dt } of steps) {
        for (const cascade of cascades) cascade.fields.update(time);
        foam.step(cascades, p.choppiness, calibration, foamCreationRate(calibration, p.foamAmount, p.foamPersistence), p.foamPersistence, dt);
      }
    },
  };
}

export const mean = (values: Float32Array) => values.reduce((sum, v) => sum + v, 0) / values.length;
