/**
 * The package's main entry, `import { Ocean } from 'three-fft-ocean'`: the ocean (Ocean), its
 * simulation, layers and rendering parts, the sea-state spectra and the `<fft-ocean>` element's
 * class. This file only re-exports.
 * @module three-fft-ocean
 */
export { Ocean, DisposedError, type OceanOptions, type OceanPath, type OceanEventMap, type SunPosition } from './ocean';
export { UnsupportedError } from './parameters/options';
export { OceanSimulation, DEFAULT_SIMULATION_OPTIONS, PATH_PREFERENCES, type SimulationOptions, type SimulationPath, type PathPreference } from './layers/oceanSimulation';
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
export { SEA_PRESETS, beaufortPreset, presetCloudCover, OVERCAST_FROM_FORCE } from './spectrum/presets';
export { cascadeBands, type CascadeBand } from './spectrum/cascadeBands';
export { orderLayers, type WaveLayer, type LayerFrame, type LayerFieldsOnCpu, type LayerQueryFields } from './layers/waveLayer';
export { FftCascade, gpuBackend, jsBackend, type FftBackend } from './layers/fftCascade';
export type { FftFieldSource, CpuFieldsForQueries } from './fft/fieldSource';
export { FloatingBody, SEA_WATER_DENSITY, type FloatingBodyOptions, type WaterSurface } from './layers/floatingBody';
export { WhitecapFoam, type FoamPath, type FoamProducer, type FoamSettings } from './layers/whitecapFoam';
export { calibrateFoam, jacobianCovariance, whitecapFraction, type FoamCalibration, type JacobianCovariance } from './layers/foamModel';
export { HullFoam } from './layers/hullFoam';
export { LocalWaves, type LocalWavesOptions, type DropOptions, type HullShape, type HullPose, type PressureSource } from './layers/localWaves';
export { CpuWaveFields } from './fft/cpuWaveFields';
export type { FloatTextureSupport } from './fft/cpuFieldTextures';
export { GpuWaveFields, supportedGpuPrecision, type GpuPrecision } from './fft/gpuWaveFields';
export { BatchedInverseFft2D } from './fft/fft';
export { OceanSurface } from './render/oceanSurface';
export type { ReflectionLayers } from './render/sceneReflection';
export { setCaptureStandIn } from './render/sceneCapture';
export { OceanMaterial, type OceanShadingOptions } from './render/oceanMaterial';
export { EYE_SIDE, type EyeSide, type RingPlacement, type SeaSurfaceMaterial, type SeaSurfaceMeshMaterial } from './render/seaSurfaceMaterial';
export {
  SHADING_MODES,
  REFRACTION_SOURCES,
  REFLECTIONS,
  SHADING_OPTIONS,
  SUN_OPTIONS,
  DEFAULT_SHADING,
  DEFAULT_SUN,
  colorToLinear,
  type ColorInput,
  type ShadingChanges,
  type ShadingMode,
  type RefractionSource,
  type Reflections,
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
export { FftOceanElement, defineFftOceanElement, FFT_OCEAN_ATTRIBUTES, type FftOceanAttribute, type RendererStatus } from './embed/fftOceanElement';
// Types that the API above takes or returns, exported so they can be named (and are in the API reference).
export type { Rgb } from './parameters/sceneOptions';
export type { OptionTable, OptionRule, OptionType } from './parameters/options';
export type { LocalWaveGrid } from './layers/localWaveModel';
export type { SkyBackground } from './render/skyBackground';
export type { SceneOutput } from './render/sceneOutput';
export type { SceneRefraction } from './render/sceneRefraction';
export type { CaptureRenderer } from './render/sceneCapture';
export { farPlaneFor, fitFarPlane } from './runtime/farPlane';
export type { AdaptiveQuality, QualityLevel, QualitySetting, QualityStep } from './runtime/adaptiveQuality';
export type { SeaStateSummary, WritableNumbers } from './ocean';
export type { Seabed, SeabedBounds, SeabedFunction, SeabedHeightfield, SeabedMap, SeabedMeshes } from './layers/seabed';
export type { Shore } from './layers/shore';
export type { WaveNumberSpectrum, SpectrumOrigin } from './spectrum/initialSpectrum';
export type { SeaStateParameters } from './spectrum/seaState';
export type { PhillipsParameters } from './spectrum/phillips';
export type { SpectrumForFields } from './fft/cpuWaveFields';
export type { PressableWater } from './layers/floatingBody';
export type { OceanMaterialInputs } from './render/oceanMaterial';
