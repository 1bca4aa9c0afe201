#pragma once
// Internal to the io library: the pieces of ImageIO.cpp that ExrFrame.cpp shares (OpenEXR colour reading with
// extra layers in the same pass, file checks and the atomic writer). Not part of the public API.

#include "core/Image.h"

#include <ImfFrameBuffer.h>
#include <ImfInputFile.h>

#include <filesystem>
#include <functional>
#include <span>

namespace photopic::detail {

/// Throws IoError unless `path` names an existing regular file.
void requireRegularFile(const std::filesystem::path& path);
/// Throws IoError unless the file opens with OpenEXR's magic number.
void requireExrFile(const std::filesystem::path& path);

/// Called once the data window is known (width x height pixels, checked) to add the caller's slices to the
/// frame buffer the colour is read through.
using ExrExtraSlices =
    std::function<void(Imf::FrameBuffer& frameBuffer, const Imath::Box2i& dataWindow, int width, int height)>;

/// The colour of an open OpenEXR file, as readImage returns it, plus whatever `extra` adds, read in the same
/// pass. Throws IoError naming `path`; OpenEXR's exceptions pass through (callers wrap them).
[[nodiscard]] ImageF readExrColor(const std::filesystem::path& path, Imf::InputFile& file,
                                  const ExrExtraSlices& extra = {});

/// Writes `bytes` to a temporary in the destination folder, fsyncs it and renames it over `path`.
void writeAtomically(const std::filesystem::path& path, std::span<const unsigned char> bytes);

} // namespace photopic::detail
