// three-fft-ocean public API: re-exports only.
export { Ocean, DisposedError, type OceanOptions, type OceanPath, type OceanEventMap, type SunPosition } from './ocean';
export { UnsupportedError } from './parameters/options';
export { OceanSimulation, DEFAULT_SIMULATION_OPTIONS, type SimulationOptions, type SimulationPath, type PathPreference } from './layers/oceanSimulation';
export {
  DEFAULT_PARAMETERS,
  ParameterError,
  SIMULATION_OPTIONS,
  SPECTRUM_MODELS,
  SPREADING_MODELS,
  validateParameters,
  parseParameterText,
  type SimulationParameters,
  type SpectrumModel,
  type SpreadingModel,
} from './parameters/parameters';
export { createCascadeSpectra, type InitialSpectrum } from './spectrum/initialSpectrum';
export { phillips } from './spectrum/phillips';
export { seaState, waveNumberSpectrum, frequencySpectrum } from './spectrum/seaState';
export { SEA_PRESETS, beaufortPreset } from './spectrum/presets';
export { cascadeBands, type CascadeBand } from './spectrum/cascadeBands';
export { orderLayers, type WaveLayer, type LayerFrame, type LayerFieldsOnCpu, type LayerQueryFields } from './layers/waveLayer';
export { FftCascade, type FftBackend } from './layers/fftCascade';
export { FloatingBody, SEA_WATER_DENSITY, type FloatingBodyOptions, type WaterSurface } from './layers/floatingBody';
export { WhitecapFoam, type FoamSettings } from './layers/whitecapFoam';
export { LocalWaves, type LocalWavesOptions, type DropOptions, type HullShape, type HullPose, type PressureSource } from './layers/localWaves';
export { CpuWaveFields } from './fft/cpuWaveFields';
export { GpuWaveFields, supportedGpuPrecision, type GpuPrecision } from './fft/gpuWaveFields';
export { BatchedInverseFft2D } from './fft/fft';
export { OceanSurface } from './render/oceanSurface';
export { OceanMaterial, type OceanShadingOptions } from './render/oceanMaterial';
export {
  SHADING_MODES,
  SHADING_OPTIONS,
  SUN_OPTIONS,
  DEFAULT_SHADING,
  DEFAULT_SUN,
  colorToLinear,
  type ColorInput,
  type ShadingChanges,
  type ShadingMode,
  type ShadingOptions,
  type SunOptions,
} from './parameters/sceneOptions';
export {
  SkyEnvironment,
  DEFAULT_SKY_ENVIRONMENT,
  type SkyEnvironmentOptions,
  skyboxFaceUrls,
  sunAnglesFromDirection,
  sunDirectionFromAngles,
  SHIPPED_SKYBOX,
  type CubeFaceUrls,
  type SunAngles,
  type SunDirection,
} from './render/skyEnvironment';
export { FftOceanElement, defineFftOceanElement, FFT_OCEAN_ATTRIBUTES, type FftOceanAttribute } from './embed/fftOceanElement';
