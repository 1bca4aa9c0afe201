#pragma once
// `photopic image`: inputs (files, patterns, layers, cameras), outputs planned and checked before the first
// frame, the settings, the pipeline and the streamed sequence (decode, GPU, encode in flight together).

#include "Command.h"
#include "Commands.h"

#include <cstdio>
#include <memory>

namespace photopic::cli {

struct DecodedFrame;

class ImageCommand final : public Command {
public:
    explicit ImageCommand(CLI::App& parent);
    ~ImageCommand() override;
    int run() override;

private:
    struct Run;

    /// The inputs, -o and whether it may overwrite, --frames and --start-number.
    void addFileOptions();
    /// What the outputs are written as, the frame rate, the telemetry, --info.
    void addFormatOptions();
    /// Cameras, lens, auxiliary outputs, jitter, channels, settings, OpenColorIO and --max-pixels.
    void addRendererOptions();
    /// How a sequence streams, --exposure-track and --preroll; the examples.
    void addSequenceOptions();

    /// The sequence's files, their channel mapping and lens values.
    void inputs();
    /// --info: each input's channels and attributes and what they feed; no rendering.
    int printInfo() const;
    /// The frames the run processes (preroll included), their cameras and the exposure track, all checked.
    void frames();
    /// The settings files, overrides and look, the OpenColorIO display, where the status lines go.
    void settings();
    /// Every path the run writes, checked (and its folders made) before any work.
    void outputs();
    /// The decoder and the first frame, the GL context and the pipeline.
    void pipeline();
    /// Each frame decoded, uploaded, processed and written, the next decode and the last write in flight.
    void stream();
    /// The last write waited for, the telemetry and the outputs committed.
    void finish();

    /// The frame before this one, read back and handed to the writer.
    void writeProcessed();
    /// --exposure-track's plan and the renderer's jitter for frame `i`.
    void beginFrame(std::size_t i, const DecodedFrame& frame, const FrameTime& time);
    /// The track, checked to hold every frame the run processes.
    void loadExposureTrack();

    ImageOptions mOptions;
    /// What one run holds, from its inputs to its last write; released (its outputs taken back unless
    /// committed) as run() returns or throws.
    std::unique_ptr<Run> mRun;
};

} // namespace photopic::cli
