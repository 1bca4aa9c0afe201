#include "FileScene.h"

#include "io/ImageIO.h"

#include <fmt/format.h>

#include <cstdio>
#include <set>

namespace photopic::viewer {

namespace {

class FileScene final : public Scene {
public:
    FileScene(std::vector<std::filesystem::path> files, FileInputs inputs)
        : mFiles(std::move(files))
        , mInputs(std::move(inputs)) {
        if (mFiles.empty()) {
            throw SceneInputError("no image file to view");
        }
        // The first file must read (no GL needed): bad input is reported before the window opens.
        decode(0);
        mExtent = {mFrame.width(), mFrame.height()};
    }

    [[nodiscard]] std::string_view name() const override { return "file"; }
    std::vector<SettingsIssue> applyOverride(std::string_view assignment) override {
        return {{.code = SettingsIssueCode::UnknownKey,
                 .path = "file",
                 .message = fmt::format("image files have no settings of their own ('{}')", assignment)}};
    }
    [[nodiscard]] std::string settingsJson() const override { return "{}"; }
    void resize(Extent) override {} // the image keeps its size; the viewer letterboxes it
    [[nodiscard]] std::vector<std::string> telemetryColumns() const override { return {}; }

    FrameInputs render(const FrameTime& time, Pipeline& pipeline, std::vector<double>&) override {
        const std::size_t index = std::size_t(time.frameIndex % mFiles.size());
        if (index != mDecoded) {
            try {
                decode(index);
            } catch (const std::exception& e) {
                if (mReported.insert(index).second) {
                    std::fprintf(stderr, "photopic-view: %s (skipped)\n", e.what());
                }
            }
        }
        if (mFrame.jittered) {
            pipeline.beginFrame(time); // the renderer jittered this frame, as `photopic image` has it
        }
        if (!mUploaded) { // a still is uploaded once; its inputs stay valid until the next upload
            mInputsUploaded = mTextures.upload(mFrame);
            mUploaded = true;
        }
        return mInputsUploaded;
    }

    [[nodiscard]] Extent extent() const { return mExtent; }

private:
    void decode(std::size_t index) {
        // A sequence played from its start again starts its decoder again: its first frame is a cut, and the
        // previous camera is not the last frame's.
        if (index == 0 || !mDecoder) {
            mDecoder.emplace(mInputs.cameras);
            mDecoder->setAovs(mInputs.aovs);
            mDecoder->setLens(mInputs.lens);
            mDecoder->setFrameNumbers(mInputs.frameNumbers);
        }
        try {
            cli::DecodedFrame frame = mDecoder->decode(mFiles[index]);
            mDecoder->recycle(std::move(mFrame));
            mFrame = std::move(frame);
        } catch (const std::exception& e) {
            throw SceneInputError(e.what());
        }
        mDecoded = index;
        mUploaded = false;
    }

    std::vector<std::filesystem::path> mFiles;
    FileInputs mInputs;
    std::set<std::size_t> mReported;
    std::optional<cli::InputDecoder> mDecoder;
    cli::DecodedFrame mFrame;
    cli::InputTextures mTextures;
    FrameInputs mInputsUploaded;
    bool mUploaded = false;
    std::size_t mDecoded = 0;
    Extent mExtent;
};

} // namespace

std::unique_ptr<Scene> makeFileScene(std::vector<std::filesystem::path> files, FileInputs inputs) {
    return std::make_unique<FileScene>(std::move(files), std::move(inputs));
}

Extent fileSceneExtent(const Scene& scene) {
    return static_cast<const FileScene&>(scene).extent();
}

} // namespace photopic::viewer
