// `photopic demo` (DemoCommand.h): its options, and which demo they choose.
#include "DemoCommand.h"

#include "CommandOptions.h"
#include "OrbitDemo.h"

#include "io/DataPath.h"

namespace photopic::cli {

DemoCommand::DemoCommand(CLI::App& parent)
    : Command(parent.add_subcommand(
          "demo", "the main demo: the tabletop walk (eye adaptation) into out/demo (or -o DIR)")) {
    CLI::App& cmd = app();
    cmd.add_option("-o,--output", mWalk.output, "output folder")->check(kOutputPath);
    cmd.add_option("--size", mSize, "WIDTHxHEIGHT")->capture_default_str();
    cmd.add_option("--fps", mWalk.fps, "frame rate")->check(CLI::Range(1.0f, 240.0f))->capture_default_str();
    cmd.add_option("--seconds", mSeconds, "length (default: the walk 22, orbit 12)")
        ->check(CLI::Range(0.1f, 600.0f));
    cmd.add_option("--scene", mScene,
                   "tabletop (default): the walk; orbit: the spacecraft's pass through the planet's shadow")
        ->check(CLI::IsMember({"tabletop", "orbit"}))
        ->capture_default_str();
    cmd.add_option("--every", mWalk.frameEvery, "write every Nth frame as PNG")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd.add_flag("--no-video", mNoVideo, "do not encode demo.mp4 even when ffmpeg is present");
    cmd.add_flag("--images", mImages,
                 "the former demo instead: every HDR image in --data through three tone curves");
    cmd.add_option("--data", mData,
                   "folder of HDR images for --images (default: $PHOTOPIC_DATA_DIR, else the installed "
                   "share/photopic/data, else the checkout's data/)");
    cmd.add_option("--preset", mWalk.preset, presetHelp("realtime (the tabletop scene's look)"));
    addMaxPixelsOption(&cmd, mMaxPixels);
    cmd.footer("Examples:\n"
               "  photopic demo                                  the walk at 320x180 into out/demo\n"
               "  photopic demo --size 960x540 --fps 60 -o out/big\n"
               "  photopic demo --scene orbit                    the orbit pass into out/demo-orbit\n"
               "  photopic demo --images --data data/            the contact sheet of every HDR image");
}

int DemoCommand::run() {
    if (mImages) {
        return runImages();
    }
    return mScene == "orbit" ? runOrbit() : runWalk();
}

int DemoCommand::runImages() const {
    const Settings look = mWalk.preset.empty() ? Settings{} : presetLook(mWalk.preset);
    return runDemo(findDataDir(mData), mWalk.output, mMaxPixels, look);
}

int DemoCommand::runOrbit() const {
    const Extent size = parseSize(mSize);
    OrbitDemoOptions orbit;
    if (app().count("--output") > 0) {
        orbit.output = mWalk.output;
    }
    orbit.width = size.width;
    orbit.height = size.height;
    orbit.fps = mWalk.fps;
    orbit.seconds = mSeconds.value_or(orbit.seconds);
    orbit.frameEvery = mWalk.frameEvery;
    orbit.video = !mNoVideo;
    orbit.preset = mWalk.preset;
    return runOrbitDemo(orbit);
}

int DemoCommand::runWalk() {
    const Extent size = parseSize(mSize);
    mWalk.seconds = mSeconds.value_or(mWalk.seconds);
    mWalk.width = size.width;
    mWalk.height = size.height;
    mWalk.video = !mNoVideo;
    return runTabletopWalk(mWalk);
}

} // namespace photopic::cli
