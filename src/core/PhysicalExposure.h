#pragma once
// Physical camera exposure (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", section 5.1): the EV100
// of the camera's aperture, shutter time and ISO, and how exposure.mode = physical hands it to the exposure
// controller. No GL.

#include "core/Camera.h"
#include "core/settings/AutoExposureSettings.h"

namespace photopic {

/// EV100 of the lens's f-number, shutter time (core/DepthOfField.h's shutterTime: the exposure time, else
/// the shutter angle's share of dt) and ISO. A closed shutter (time 0) counts as 1e-6 s.
[[nodiscard]] float cameraEv100(const Lens& lens, float dt) noexcept;

/// log2 of the exposure multiplier of the camera: log2(1 / (1.2 * 2^EV100)).
[[nodiscard]] float cameraExposureLog2(const Lens& lens, float dt) noexcept;

/// Physical mode through the ordinary controller: the camera's exposure joins the manual EV, and auto
/// exposure's target is measured on the camera-exposed image (its compensation lowered by the same amount),
/// so the adapted value is a correction clamped to [minEV, maxEV] around the camera's exposure.
struct PhysicalExposureInputs {
    AutoExposureSettings autoExposure;
    float manualEV = 0.0f;
};
[[nodiscard]] PhysicalExposureInputs physicalExposure(const AutoExposureSettings& autoExposure,
                                                      float manualEV, const Lens& lens, float dt) noexcept;
/// The same around a camera exposure already known (`cameraLog2`, cameraExposureLog2's value, e.g. from a
/// meter file); a non-finite one leaves the inputs as they are.
[[nodiscard]] PhysicalExposureInputs physicalExposure(const AutoExposureSettings& autoExposure,
                                                      float manualEV, float cameraLog2) noexcept;

} // namespace photopic
