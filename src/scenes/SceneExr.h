#pragma once
// A scene's frame inputs as an EXR frame in the file conventions of io/ExrFrame.h, so `photopic image` reads
// back what a 3D scene rendered.

#include "io/ExrFrame.h"
#include "pipeline/Pipeline.h"

namespace photopic {

/// Reads the frame's textures back (blocking): colour as is; depth as linear view depth (Z); normals turned
/// from view into world space (N); motion from UV (v up) into pixels (x right, y down); the camera's
/// attributes. Layers the inputs lack stay empty; depth and normals need the camera.
[[nodiscard]] ExrFrame exrFrameFromInputs(const FrameInputs& inputs);

} // namespace photopic
