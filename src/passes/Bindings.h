#pragma once
// Binding indices and GPU struct mirrors shared by C++ and GLSL (one header for both, so the two cannot drift
// apart). The same numbers are injected into every shader as #defines (see bindingDefines()).

#include "gl/ShaderLibrary.h"

#include <cstddef>
#include <cstdint>

namespace photopic {

inline constexpr unsigned kBindingExposureState = 0; ///< SSBO: GpuExposureState
inline constexpr unsigned kBindingHistogram = 1; ///< SSBO: 256 uint histogram bins (core/Metering.h binning)
inline constexpr unsigned kBindingMetering = 2;  ///< SSBO: GpuMeteringHeader + per-workgroup partial sums
inline constexpr unsigned kBindingProbe = 3; ///< SSBO: GpuProbeHeader + GpuProbeEntry[] (this frame's probes)
inline constexpr unsigned kBindingSubjectState = 4; ///< SSBO: GpuSubjectState (persists across frames)
/// SSBO: the running pass's tile list, for its indirect dispatches (SMAA's tiles with an edge, motion blur's
/// moving and still tiles), one per dispatch like the parameter block
inline constexpr unsigned kBindingTileList = 5;
/// UBO: the running pass's std140 parameter block (ParameterBlock<T> in gl/Objects.h), one per dispatch.
inline constexpr unsigned kBindingParameters = 0;
/// UBO: the same buffer as kBindingExposureState, bound as a uniform block for the passes that only read it
/// (every member a 4-byte scalar, so std140 and std430 lay it out alike). A storage-buffer load is a loop
/// over the SIMD lanes on llvmpipe; a uniform block is one scalar load (7% of the composite's instructions).
inline constexpr unsigned kBindingExposureUniform = 1;

/// std430 mirror of passes/common/exposure.h.glsl. The first six fields are core's ExposureState
/// (core/ExposureController.h) in the same order; the rest is what the pipeline and its readers add.
struct GpuExposureState {
    float appliedLog2 = 0;      ///< EV, adapted auto exposure (without manual EV)
    float targetLog2 = 0;       ///< EV, target of the last valid reading
    float meteredLuminance = 0; ///< last valid metered luminance (0 before the first)
    float exposure = 1;         ///< total multiplier applied to the frame: 2^(manualEV + appliedLog2)
    int adapting = 0;           ///< deadband hysteresis state
    int initialized = 0;        ///< 0: the next valid reading snaps
    float manualEV = 0;         ///< EV, tonemapping.exposure of this frame
    int autoEnabled = 0;        ///< autoExposure.enabled of this frame
    float frameLuminance = 0;   ///< this frame's own reading, 0 when none (not metered, nothing meterable)
    float minLuminance = 0;     ///< smallest meterable pixel luminance of this frame, 0 when not metered
    float maxLuminance = 0;     ///< largest meterable pixel luminance of this frame, 0 when not metered
    std::uint32_t histogramCount = 0; ///< pixels in the histogram this frame, 0 when it was not built
    float histogramLowLog2 = 0;       ///< percentile window's low edge (bin centre), core HistogramStats
    float histogramHighLog2 = 0;      ///< percentile window's high edge (bin centre)
    float histogramAverageLog2 = 0;   ///< mean log2 L over the window
    std::uint32_t histogramPeak = 0;  ///< largest bin count (scales the overlay)
};
static_assert(sizeof(GpuExposureState) == 64);
static_assert(offsetof(GpuExposureState, appliedLog2) == 0 && offsetof(GpuExposureState, targetLog2) == 4 &&
              offsetof(GpuExposureState, meteredLuminance) == 8 &&
              offsetof(GpuExposureState, exposure) == 12 && offsetof(GpuExposureState, adapting) == 16 &&
              offsetof(GpuExposureState, initialized) == 20 && offsetof(GpuExposureState, manualEV) == 24 &&
              offsetof(GpuExposureState, autoEnabled) == 28);
static_assert(offsetof(GpuExposureState, frameLuminance) == 32 &&
              offsetof(GpuExposureState, minLuminance) == 36 &&
              offsetof(GpuExposureState, maxLuminance) == 40 &&
              offsetof(GpuExposureState, histogramCount) == 44 &&
              offsetof(GpuExposureState, histogramLowLog2) == 48 &&
              offsetof(GpuExposureState, histogramHighLog2) == 52 &&
              offsetof(GpuExposureState, histogramAverageLog2) == 56 &&
              offsetof(GpuExposureState, histogramPeak) == 60);

inline constexpr int kGpuHistogramBins = 256;
inline constexpr std::size_t kGpuHistogramBytes = kGpuHistogramBins * sizeof(std::uint32_t);

/// std430 mirror of the header of passes/metering/metering.h.glsl's buffer; `vec2 partials[]` follows it
/// (x = sum of w log2 L, y = sum of w, one per metering workgroup).
struct GpuMeteringHeader {
    std::uint32_t minBits = 0; ///< float bits of the smallest meterable L (positive floats order as uints)
    std::uint32_t maxBits = 0; ///< float bits of the largest meterable L; 0: none this frame
    std::uint32_t groups = 0;  ///< partial sums written by the metering dispatch
    std::uint32_t pad0 = 0;
    float reading = 0;   ///< the weighted mean luminance (reduce dispatch), 0: no reading
    float weightSum = 0; ///< sum of weights that entered it (diagnostics)
    float pad1 = 0;
    float pad2 = 0;
};
static_assert(sizeof(GpuMeteringHeader) == 32);
static_assert(offsetof(GpuMeteringHeader, groups) == 8 && offsetof(GpuMeteringHeader, reading) == 16 &&
              offsetof(GpuMeteringHeader, weightSum) == 20);

/// std430 mirror of the header of passes/probe/probe.comp.glsl's buffer; `GpuProbeEntry entries[]` follows
/// it. The CPU writes the header and the entries' uv/id each frame; the probe dispatch fills `luma`; the
/// buffer then goes whole into the probe readback ring.
struct GpuProbeHeader {
    std::uint32_t count = 0;      ///< entries probed this frame
    std::int32_t taps = 5;        ///< 1, 5 or 9 (kProbeTaps)
    float radius = 0.02f;         ///< image heights
    std::int32_t selected = -1;   ///< entry of the subject of the view when it is probed this frame, else -1
    std::int32_t active = 0;      ///< 1: there is a subject of the view (its kept luma is the reading)
    std::uint32_t selectedId = 0; ///< id of the subject of the view
    float deadbandEV = 0.05f;     ///< SubjectSettings probe.deadbandEV
    float timeS = 0.0f;           ///< frame time of these probes (SubjectTracker::time()), for lastProbeAt
};
static_assert(sizeof(GpuProbeHeader) == 32);
static_assert(offsetof(GpuProbeHeader, selected) == 12 && offsetof(GpuProbeHeader, selectedId) == 20 &&
              offsetof(GpuProbeHeader, timeS) == 28);

/// std430 mirror of one probe entry (passes/probe/probe.comp.glsl).
struct GpuProbeEntry {
    float u = 0.5f; ///< image UV, u right
    float v = 0.5f; ///< image UV, v down
    std::uint32_t id = 0;
    float luma = 0; ///< written by the probe: mean Rec.709 luma of the taps (core probeImage)
};
static_assert(sizeof(GpuProbeEntry) == 16 && offsetof(GpuProbeEntry, id) == 8 &&
              offsetof(GpuProbeEntry, luma) == 12);

/// std430 mirror of passes/probe/probe.comp.glsl's persistent subject state: the luma `subject` metering
/// reads, kept on the GPU between probes.
struct GpuSubjectState {
    float keptLuma = 0;       ///< the subject's luma after the deadband; 0: none yet
    std::uint32_t keptId = 0; ///< whose it is
    std::int32_t hasKept = 0; ///< 1: keptLuma belongs to keptId
    std::uint32_t pad = 0;
};
static_assert(sizeof(GpuSubjectState) == 16 && offsetof(GpuSubjectState, hasKept) == 8);

/// #defines every shader gets: the binding indices above.
ShaderDefines bindingDefines(ShaderDefines extra = {});

/// Binds the exposure state buffer (GpuExposureState) where the passes that only read it find it: the
/// uniform block at kBindingExposureUniform (passes/common/exposure.h.glsl). The adaptation pass, its one
/// writer, binds it as a storage buffer at kBindingExposureState.
void bindExposureStateForReading(const Buffer& state);

} // namespace photopic
