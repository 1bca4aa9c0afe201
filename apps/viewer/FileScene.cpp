#include "FileScene.h"

#include "gl/TextureIo.h"
#include "io/ImageIO.h"

#include <fmt/format.h>

#include <cstdio>
#include <set>

namespace photopic::viewer {

namespace {

class FileScene final : public Scene {
public:
    explicit FileScene(std::vector<std::filesystem::path> files)
        : mFiles(std::move(files)) {
        if (mFiles.empty()) {
            throw SceneInputError("no image file to view");
        }
        // The first file must read (no GL needed): bad input is reported before the window opens.
        decode(0);
        mExtent = {mImage.width, mImage.height};
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

    FrameInputs render(const FrameTime& time, Pipeline&, std::vector<double>&) override {
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
        if (!mUploaded) {
            if (!mTexture.valid() || mTexture.extent() != Extent{mImage.width, mImage.height}) {
                mTexture = makeTexture(mImage, "viewer file");
            } else {
                mTexture.uploadRgba32f(mImage.rgba.data());
            }
            mUploaded = true;
        }
        return {.color = &mTexture};
    }

    [[nodiscard]] Extent extent() const { return mExtent; }

private:
    void decode(std::size_t index) {
        try {
            mImage = readImage(mFiles[index]);
        } catch (const std::exception& e) {
            throw SceneInputError(e.what());
        }
        mDecoded = index;
        mUploaded = false;
    }

    std::vector<std::filesystem::path> mFiles;
    std::set<std::size_t> mReported;
    ImageF mImage;
    Texture mTexture;
    std::size_t mDecoded = 0;
    bool mUploaded = false;
    Extent mExtent;
};

} // namespace

std::unique_ptr<Scene> makeFileScene(std::vector<std::filesystem::path> files) {
    return std::make_unique<FileScene>(std::move(files));
}

Extent fileSceneExtent(const Scene& scene) {
    return static_cast<const FileScene&>(scene).extent();
}

} // namespace photopic::viewer
