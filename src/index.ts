// three-fft-ocean public API: re-exports only.
export { Ocean, type OceanOptions } from './ocean';
export { OceanSimulation, type SimulationOptions, type SimulationPath, type PathPreference } from './sim/oceanSimulation';
export { DEFAULT_PARAMETERS, ParameterError, validateParameters, type SimulationParameters } from './sim/parameters';
export { createInitialSpectrum, phillips, type InitialSpectrum } from './sim/spectrum';
export { CpuWaveFields } from './sim/cpuWaveFields';
export { GpuWaveFields, supportedGpuPrecision, type GpuPrecision } from './sim/gpuWaveFields';
export { BatchedInverseFft2D } from './sim/fft';
export { OceanSurface } from './render/oceanSurface';
export { OceanMaterial, SHADING_MODES, type ShadingMode, type OceanShadingOptions } from './render/oceanMaterial';
export { SkyEnvironment, skyboxFaceUrls, SHIPPED_SKYBOX, type CubeFaceUrls } from './render/skyEnvironment';
export { FftOceanElement, defineFftOceanElement, FFT_OCEAN_ATTRIBUTES, type FftOceanAttribute } from './embed/fftOceanElement';
