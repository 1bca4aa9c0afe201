#pragma once
// Device motion for the canvas scene: pitch/roll/yaw samples from a CSV file or a built-in
// scripted tilt, interpolated by frame time, and the light vector it gives. No GL here, so all of it is
// unit-tested.

#include <glm/vec3.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace photopic {

/// Device attitude at one instant, radians (CoreMotion's CMAttitude order: pitch about x, roll about y, yaw
/// about z).
struct Attitude {
    double pitch = 0; ///< rad; positive moves the lamp's highlight up the image
    double roll = 0;  ///< rad; positive moves the lamp's highlight right
    double yaw = 0;   ///< rad, carried to telemetry; the light vector does not use it
};

struct MotionSample {
    double time = 0; ///< s, strictly increasing along a track
    Attitude attitude;
};

/// A motion CSV could not be read: what() is "FILE:LINE: problem" (or "FILE: problem" without a line).
class MotionError : public std::runtime_error {
public:
    MotionError(std::string_view file, int line, std::string_view problem);
    [[nodiscard]] int line() const { return mLine; }

private:
    int mLine;
};

/// Samples with linear interpolation in time; times before the first or after the last sample clamp to it.
class MotionTrack {
public:
    MotionTrack() = default;
    /// Throws std::invalid_argument unless every time and angle is finite and the times strictly increase.
    explicit MotionTrack(std::vector<MotionSample> samples);
    /// Defined for every argument: NaN and -inf give the first sample, +inf the last; the result is finite.
    [[nodiscard]] Attitude at(double time) const;
    [[nodiscard]] const std::vector<MotionSample>& samples() const { return mSamples; }

private:
    std::vector<MotionSample> mSamples;
};

/// The expected header, exactly (CSV, radians).
inline constexpr std::string_view kMotionCsvHeader = "time_s,pitch,roll,yaw";

/// Parses CSV text: the header line above, then one `time_s,pitch,roll,yaw` row per line, at least one row,
/// strictly increasing time, finite numbers. Blank lines are skipped; CRLF is accepted. `fileName` only names
/// the source in errors (MotionError with the 1-based line).
MotionTrack parseMotionCsv(std::string_view text, std::string_view fileName);
/// Reads and parses a file; a missing or unreadable file is a MotionError naming it.
MotionTrack loadMotionCsv(const std::filesystem::path& path);

/// The built-in scripted tilt: a Lissajous sweep, roll on one period and pitch on 1.5 periods, so the lamp's
/// highlight travels left-right and up-down and comes back after 2 periods. Starts level (0, 0) at t = 0.
struct ScriptedTilt {
    double period = 6.0;          ///< s, > 0: one roll oscillation
    double rollAmplitude = 0.35;  ///< rad
    double pitchAmplitude = 0.25; ///< rad
    [[nodiscard]] Attitude at(double time) const;
};

/// The tilt-to-lamp rule: normalize(sin(roll), sin(pitch), -cos(pitch) cos(roll)) -- "the lamp over the
/// user's shoulder". The frame is a Metal-style canvas frame: x right, y up, z into the screen, so the
/// canvas faces the viewer along -z and the vector points from the canvas towards the lamp. Level -> (0, 0,
/// -1).
glm::vec3 seedLightVector(double pitch, double roll);

/// The same direction in Photopic's canvas frame (x right, y up, z out of the canvas towards the viewer, the
/// frame the material normals use): z flipped. Level -> (0, 0, 1), the lamp straight behind the viewer.
glm::vec3 canvasLightDirection(double pitch, double roll);

} // namespace photopic
