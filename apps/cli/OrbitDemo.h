#pragma once
// `photopic demo --scene orbit`: the orbit scene's scripted pass (the ship into the planet's shadow and back
// into the sun) through the pipeline with auto exposure, then frame PNGs, telemetry.csv, an exposure plot,
// a contact sheet of evenly spaced frames and an MP4 when ffmpeg is there.

#include <filesystem>
#include <string>

namespace photopic::cli {

struct OrbitDemoOptions {
    std::filesystem::path output = "out/demo-orbit";
    int width = 320; ///< 320x180 at 30 fps for 12 s: about 20 s on llvmpipe (2 cores)
    int height = 180;
    float fps = 30.0f;
    float seconds = 12.0f; ///< the script: the eclipse runs from about 4.3 s to 8.4 s
    int frameEvery = 1;    ///< write every Nth frame as PNG (the MP4 then runs at fps / N)
    bool video = true;     ///< encode demo.mp4 when the ffmpeg command is present
    std::string preset;    ///< --preset NAME: that look over the scene's settings; empty: the scene's own
};

int runOrbitDemo(const OrbitDemoOptions& options);

} // namespace photopic::cli
