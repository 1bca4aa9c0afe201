// The bench's bandwidth references (CopyReference.h).
#include "CopyReference.h"

#include "gl/ShaderLibrary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace photopic::cli {

namespace {

/// Rows 0, height / 2 and height - 1 of level 0 of `texture` as RGBA floats.
std::vector<float> sampleRows(const Texture& texture) {
    const Extent e = texture.extent();
    std::vector<float> rows;
    for (const int y : {0, e.height / 2, e.height - 1}) {
        const std::size_t at = rows.size(), count = std::size_t(e.width) * 4;
        rows.resize(at + count);
        glGetTextureSubImage(texture.id(), 0, 0, y, 0, e.width, 1, 1, GL_RGBA, GL_FLOAT,
                             GLsizei(count * sizeof(float)), rows.data() + at);
    }
    return rows;
}

/// A reference's median time: `run` warmed up, then timed as the passes are.
template <class Work>
double timeReference(const BenchOptions& options, QueueAhead* ahead, const Work& run) {
    for (int i = 0; i < options.warmup; ++i) {
        run();
    }
    return medianTimed(options, ahead, run, [] {});
}

} // namespace

/// GLSL image format qualifier of the formats a frame comes in.
std::string imageFormatName(GLenum format) {
    switch (format) {
    case GL_RGBA32F:
        return "rgba32f";
    case GL_RGBA8:
        return "rgba8";
    default:
        return "rgba16f";
    }
}

/// The reference copy of `source` (the frame's texture, or the one-value texture: `what`) into a texture of
/// its format and size. Throws when the copy did not reproduce its source.
CopyReference measureCopy(const Texture& source, const char* what, const BenchOptions& options,
                          QueueAhead* ahead) {
    const GLenum format = source.format();
    if (format != GL_RGBA32F && format != GL_RGBA16F && format != GL_RGBA8) {
        throw std::logic_error(fmt::format("bench: no reference copy of GL format {:#x}", format));
    }
    const std::string name = imageFormatName(format);
    const Extent e = source.extent();
    const Program program = makeComputeProgram("gl/bandwidth_copy.comp.glsl", {{"FORMAT", name}});
    const Texture target({.extent = e, .format = format, .debugName = "bench copy target"});
    const auto copy = [&] {
        program.use();
        glBindTextureUnit(0, source.id());
        glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
        dispatchPixels(e);
        imageWriteBarrier();
    };
    CopyReference r{
        .format = name, .source = what, .bytes = 2.0 * double(e.width) * e.height * bytesPerTexel(format)};
    r.medianMs = timeReference(options, ahead, copy);
    // A copy that did not copy would make every fraction meaningless: a copy into the same format gives
    // back every value as it was.
    const std::vector<float> in = sampleRows(source), out = sampleRows(target);
    const bool same = std::ranges::equal(
        in, out, [](float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); });
    if (!same) {
        throw std::runtime_error(
            fmt::format("bench: the bandwidth reference copy of the {} did not reproduce its input", what));
    }
    return r;
}

/// The reduction reference: the 2x2 box mean of `source` into an RGBA16F texture of half its size, timed as
/// the copy is. A pass that reads the whole frame and writes a quarter of it (the bloom prefilter) moves its
/// bytes at no more than this pace: its share of the copy's is that kind of pass's ceiling on the device.
/// Throws when the means are not the source's.
CopyReference measureReduction(const Texture& source, const BenchOptions& options, QueueAhead* ahead) {
    const Extent e = source.extent();
    const Extent half{e.width / 2, e.height / 2}; // the bench's frames are 8x8 at least
    const Program program = makeComputeProgram("gl/bandwidth_reduce.comp.glsl", {});
    const Texture target({.extent = half, .format = GL_RGBA16F, .debugName = "bench reduction target"});
    const auto reduce = [&] {
        program.use();
        glBindTextureUnit(0, source.id());
        glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
        dispatchPixels(half);
        imageWriteBarrier();
    };
    CopyReference r{.format = "rgba16f",
                    .source = "frame, 2x2 box mean at half size",
                    .bytes = double(e.width) * e.height * bytesPerTexel(source.format()) +
                             double(half.width) * half.height * bytesPerTexel(GL_RGBA16F)};
    r.medianMs = timeReference(options, ahead, reduce);
    // Its first row against the mean of the source's first two, within the rounding to halves.
    const int w = e.width;
    std::vector<float> in(std::size_t(w) * 2 * 4), out(std::size_t(half.width) * 4);
    glGetTextureSubImage(source.id(), 0, 0, 0, 0, w, 2, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(in.size() * sizeof(float)), in.data());
    glGetTextureSubImage(target.id(), 0, 0, 0, 0, half.width, 1, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(out.size() * sizeof(float)), out.data());
    for (int x = 0; x < half.width; ++x) {
        for (int c = 0; c < 4; ++c) {
            const auto at = [&](int px, int py) { return in[(std::size_t(py) * w + px) * 4 + c]; };
            const float mean = 0.25f * (at(2 * x, 0) + at(2 * x + 1, 0) + at(2 * x, 1) + at(2 * x + 1, 1));
            const float got = out[std::size_t(x) * 4 + c];
            const bool ok = (std::isnan(mean) && std::isnan(got)) ||
                            (std::abs(mean) > 65504.0f && std::isinf(got)) ||
                            std::abs(got - mean) <= 1e-3f * std::abs(mean) + 1e-7f;
            if (!ok) {
                throw std::runtime_error(fmt::format("bench: the reduction reference gave {} where the mean "
                                                     "of its texels is {} (texel {}, channel {})",
                                                     got, mean, x, c));
            }
        }
    }
    return r;
}

/// A texture of `extent` and `format` cleared to one colour: the source of the copy earlier records used.
Texture constantTexture(Extent extent, GLenum format) {
    Texture texture({.extent = extent, .format = format, .debugName = "bench one-value copy source"});
    const float value[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, value);
    return texture;
}

} // namespace photopic::cli
