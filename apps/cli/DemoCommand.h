#pragma once
// `photopic demo`: the tabletop walk (TabletopDemo.h), `--scene orbit` the orbit pass (OrbitDemo.h), or
// `--images` every HDR image of a folder through three tone curves (runDemo).

#include "Command.h"
#include "Commands.h"
#include "TabletopDemo.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace photopic::cli {

class DemoCommand final : public Command {
public:
    explicit DemoCommand(CLI::App& parent);
    int run() override;

private:
    /// --images: the contact sheets of every HDR image in --data.
    int runImages() const;
    /// --scene orbit.
    int runOrbit() const;
    /// The tabletop walk (the default).
    int runWalk();

    TabletopWalkOptions mWalk;
    std::string mScene = "tabletop";
    std::optional<float> mSeconds; // unset: the chosen scene's own length
    std::filesystem::path mData;   // empty: findDataDir() looks it up
    std::string mSize = "320x180";
    bool mNoVideo = false;
    bool mImages = false;
    std::int64_t mMaxPixels = kDefaultMaxPixels;
};

} // namespace photopic::cli
