// three-fft-ocean public API: re-exports only.
export { Ocean, type OceanOptions } from './ocean';
export { OceanSimulation, type SimulationOptions, type SimulationPath, type PathPreference } from './layers/oceanSimulation';
export { DEFAULT_PARAMETERS, ParameterError, validateParameters, type SimulationParameters } from './parameters/parameters';
export { createInitialSpectrum, phillips, type InitialSpectrum } from './spectrum/initialSpectrum';
export { CpuWaveFields } from './fft/cpuWaveFields';
export { GpuWaveFields, supportedGpuPrecision, type GpuPrecision } from './fft/gpuWaveFields';
export { BatchedInverseFft2D } from './fft/fft';
export { OceanSurface } from './render/oceanSurface';
export { OceanMaterial, SHADING_MODES, type ShadingMode, type OceanShadingOptions } from './render/oceanMaterial';
export { SkyEnvironment, skyboxFaceUrls, SHIPPED_SKYBOX, type CubeFaceUrls } from './render/skyEnvironment';
export { FftOceanElement, defineFftOceanElement, FFT_OCEAN_ATTRIBUTES, type FftOceanAttribute } from './embed/fftOceanElement';
