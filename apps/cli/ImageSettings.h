#pragma once
// The settings a `photopic image` run (and `photopic meter`, which meters as it renders) works with: the
// stills look under the settings sources, what an image cannot do turned off with a word, the OpenColorIO
// display, and the pipeline made from them.

#include "Commands.h"
#include "OcioDisplay.h"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>

namespace photopic::cli {

/// The run's settings (the stills look under the preset, file and overrides) with --bit-depth over them.
Settings imageSettings(const ImageOptions& options);
/// The pipeline for `photopic image`, its creation errors turned into InputError where the user can fix them.
std::unique_ptr<Pipeline> makeImagePipeline(const PipelineCreateInfo& createInfo);

/// The OpenColorIO display/view transform when --ocio-* asks for it, its config and names checked before
/// any output exists. It makes display images, so every output must be one (PNG, TIFF, JPEG).
std::optional<OcioDisplay> ocioDisplayFor(const ImageOptions& options);

/// The anti-aliasing an image run cannot do, turned off with one warning that says why and what runs
/// instead (SMAA under taa+smaa, else FXAA when its switch is on, else nothing): TAA gathers each pixel over
/// earlier frames, and a single image has none; SSAA renders each frame several times, which only the
/// renderer that made the image could.
void dropUnavailableAa(Settings& settings, std::size_t inputCount);

/// A debug view the frame cannot make is an error naming what it lacks, not the plain image the pipeline
/// would show instead.
void requireDebugViewMade(const Pipeline& pipeline, const Settings& settings,
                          const std::filesystem::path& input);

} // namespace photopic::cli
