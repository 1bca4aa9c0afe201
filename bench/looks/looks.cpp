// photopic_looks: measures every tone curve the library offers, so the stills preset's curve can be chosen by
// figures (docs/looks.md). Prints the markdown tables to stdout and writes contact sheets and light crops.
//
//   photopic_looks [--out DIR] [--data DIR] [--cli PATH] [--hue-only] [--crops-without-bloom]
//                  [--keep DIR]
//
// 1. Hue: the CPU curves (core/ToneCurves.h, the GPU's reference) on an exposure ramp of test colours.
// 2. Clipping: data/ images and a synthetic scene through the photopic CLI, stills preset, bloom off.
// 3. Images: a contact sheet per image (bloom off) and 4x crops of its light source (bloom on, as stills
//    renders lights, unless --crops-without-bloom).

#include "HueSweep.h"
#include "ImageRuns.h"

#include "core/Color.h"
#include "io/ImageIO.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using namespace looks;

struct Options {
    fs::path out = "docs/images/looks";
    fs::path data = PHOTOPIC_LOOKS_DATA_DIR;
    fs::path cli = PHOTOPIC_LOOKS_CLI;
    bool hueOnly = false;
    bool cropBloom = true;
    fs::path keep; ///< empty: the full-size renders go to a temporary folder
};

Options parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool hasValue = i + 1 < argc;
        if (arg == "--hue-only") {
            options.hueOnly = true;
        } else if (arg == "--crops-without-bloom") {
            options.cropBloom = false;
        } else if (arg == "--out" && hasValue) {
            options.out = argv[++i];
        } else if (arg == "--data" && hasValue) {
            options.data = argv[++i];
        } else if (arg == "--keep" && hasValue) {
            options.keep = argv[++i];
        } else if (arg == "--cli" && hasValue) {
            options.cli = argv[++i];
        } else {
            throw std::runtime_error(
                "photopic_looks: unknown option or missing value: " + arg +
                " (usage: photopic_looks [--out DIR] [--data DIR] [--cli PATH] [--hue-only]"
                " [--crops-without-bloom] [--keep DIR])");
        }
    }
    return options;
}

std::string format(const char* pattern, double a, double b) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, a, b);
    return text;
}

/// The table's first two lines: "| curve |" and a column a name, then the separator.
void printTableHead(const std::vector<std::string>& columns) {
    std::printf("| curve |");
    for (const std::string& c : columns) {
        std::printf(" %s |", c.c_str());
    }
    std::printf("\n|---|");
    for (std::size_t i = 0; i < columns.size(); ++i) {
        std::printf("---|");
    }
    std::printf("\n");
}

/// A table of a row a curve and a column a colour, each cell `cell` of the colour's hue sweep.
template <class Cell>
void printColourTable(const std::vector<Variant>& variants, const std::vector<TestColour>& colours, Cell cell) {
    std::vector<std::string> names;
    for (const TestColour& c : colours) {
        names.push_back(c.name);
    }
    printTableHead(names);
    for (const Variant& v : variants) {
        std::printf("| %s |", v.label.c_str());
        for (const TestColour& c : colours) {
            std::printf(" %s |", cell(measureHueShift(v, c.linear)).c_str());
        }
        std::printf("\n");
    }
    std::printf("\n");
}

void printHueTable(const char* title, const std::vector<Variant>& variants,
                   const std::vector<TestColour>& colours) {
    std::printf(
        "### %s: worst Oklab hue shift, degrees (at EV), -2 to +6 EV, until chroma < 10%% of peak\n\n",
        title);
    printColourTable(variants, colours, [](const HueShift& s) {
        return format("%+.0f (%+.1f)", double(s.worstDeg), double(s.worstAtEv));
    });
}

void printChromaTable(const std::vector<Variant>& variants) {
    std::printf("### Oklab saturation (C/L) at 0 EV, %% of the input's (100: as saturated as the colour "
                "shown as it is)\n\n");
    printColourTable(variants, testColours(), [](const HueShift& s) {
        return format("%.0f", 100.0 * double(s.saturationKeptAtMid), 0.0);
    });
}

void printMidTable(const std::vector<Variant>& variants) {
    std::printf(
        "### Hue shift at 0 EV (luminance 0.18), degrees; first EV under 10%% chroma in brackets\n\n");
    printColourTable(variants, testColours(), [](const HueShift& s) {
        return s.whiteAtEv <= kRampLastEv ? format("%+.0f [%+.1f]", double(s.atMidDeg), double(s.whiteAtEv))
                                          : format("%+.0f [-]", double(s.atMidDeg), 0.0);
    });
}

constexpr float kNeverEv = 16.0f;

// The first EV (0.05 steps, relative to grey 0.18) at which the sRGB code of grey's output luminance passes
// `code` going up; kNeverEv when it does not by then (golden's tint keeps its luminance under 250).
float greyCrossingEv(const Variant& v, float code) {
    const photopic::ToneCurveParams params{.agxLook = v.look};
    for (float ev = -kNeverEv; ev < kNeverEv; ev += 0.05f) {
        const glm::vec3 out = photopic::toneMap(v.mapper, glm::vec3(0.18f * std::exp2(ev)), params);
        if (photopic::srgbEncode(photopic::luma709(out)) * 255.0f >= code) {
            return ev;
        }
    }
    return kNeverEv;
}

void printRangeTable(const std::vector<Variant>& variants) {
    std::printf(
        "### Grey through each curve: EV over 0.18 where its output luminance reaches code 10, 118, 250\n\n");
    std::printf("| curve | code 10 | code 118 (display mid grey) | code 250 | stops from 10 to 250 |\n");
    std::printf("|---|---|---|---|---|\n");
    for (const Variant& v : variants) {
        const float low = greyCrossingEv(v, 10.0f), mid = greyCrossingEv(v, 118.0f);
        const float high = greyCrossingEv(v, 250.0f);
        const std::string top = high >= kNeverEv ? "never" : format("%+.2f", double(high), 0.0);
        const std::string stops = high >= kNeverEv ? "-" : format("%.1f", double(high - low), 0.0);
        std::printf("| %s | %+.2f | %+.2f | %s | %s |\n", v.label.c_str(), double(low), double(mid),
                    top.c_str(), stops.c_str());
    }
    std::printf("\n");
}

struct TestImage {
    std::string label; ///< the tables' column and the PNG names' stem
    fs::path path;
    std::optional<std::pair<int, int>> lightAt; ///< crop centre; none: the brightest input pixel
};

std::vector<TestImage> testImages(const Options& options, const fs::path& workDir) {
    const fs::path synthetic = workDir / "synthetic.exr";
    photopic::writeExr(synthetic, makeSyntheticScene());
    // Crops chosen by eye from the full-size renders where the brightest pixel says nothing: Desk's is inside
    // a pane that every curve renders white, so its crop is a red jewel of the rosette at the window's
    // centre; GoldenGate's is a city light across the bay, so its crop is the deck lamps of the main span.
    const std::pair<int, int> rosette{316, 320};
    return {
        {"Desk.exr", options.data / "Desk.exr", rosette},
        {"Desk.hdr", options.data / "Desk.hdr", rosette},
        {"GoldenGate.exr", options.data / "GoldenGate.exr", std::pair{600, 463}},
        {"blender_sunrise.exr", options.data / "blender_sunrise.exr", std::nullopt},
        {"synthetic", synthetic, std::pair{kSyntheticCropX, kSyntheticLightY}},
    };
}

std::string stem(const std::string& label) {
    std::string s = label;
    for (char& c : s) {
        c = c == '.' ? '-' : c;
    }
    return s;
}

// Sheets at most 440 px wide and crop tiles 454 (docs/images/looks stays small): 4 cells a row, 5 for
// portrait images so their sheet is not twice as tall.
constexpr int kSheetWidth = 440, kCropSize = 28;

int columnsFor(const photopic::ImageF& image) {
    return image.width >= image.height ? 4 : 5;
}

struct ImageFigures {
    std::vector<ClipShare> fixed, automatic; ///< one per variant
};

ImageFigures measureImage(const Options& options, const CliRun& run, const TestImage& image,
                          const std::vector<Variant>& variants) {
    const photopic::ImageF input = photopic::readImage(image.path);
    const auto [cx, cy] = image.lightAt.value_or(brightestPixel(input));
    const int columns = columnsFor(input);
    ImageFigures figures;
    std::vector<photopic::Image8> thumbnails, crops;
    for (const Variant& v : variants) {
        const photopic::Image8 fixed = renderWithCli(run, image.path, v, Exposure::Fixed, false);
        figures.fixed.push_back(clipShare(fixed));
        figures.automatic.push_back(clipShare(renderWithCli(run, image.path, v, Exposure::Auto, false)));
        thumbnails.push_back(shrink(fixed, (kSheetWidth - (columns - 1) * kTileGutter) / columns));
        const photopic::Image8 lit =
            options.cropBloom ? renderWithCli(run, image.path, v, Exposure::Fixed, true) : fixed;
        crops.push_back(crop4x(lit, cx, cy, kCropSize));
        std::fprintf(stderr, "photopic_looks: %s %s done\n", image.label.c_str(), v.label.c_str());
    }
    photopic::writePng(options.out / (stem(image.label) + "-sheet.png"), tile(thumbnails, columns));
    photopic::writePng(options.out / (stem(image.label) + "-light.png"), tile(crops, 4));
    std::fprintf(stderr, "photopic_looks: %s light crop centred on (%d, %d)\n", image.label.c_str(), cx, cy);
    return figures;
}

void printClipTable(const char* title, const std::vector<Variant>& variants,
                    const std::vector<TestImage>& images, const std::vector<std::vector<ClipShare>>& shares) {
    std::printf("### %s: %% of pixels crushed (every channel < 10) / clipped (any channel > 250)\n\n", title);
    std::vector<std::string> names;
    for (const TestImage& image : images) {
        names.push_back(image.label);
    }
    printTableHead(names);
    for (std::size_t v = 0; v < variants.size(); ++v) {
        std::printf("| %s |", variants[v].label.c_str());
        for (std::size_t i = 0; i < images.size(); ++i) {
            const ClipShare& s = shares[i][v];
            std::printf(" %s |", format("%.2f / %.2f", s.crushedPercent, s.clippedPercent).c_str());
        }
        std::printf("\n");
    }
    std::printf("\n");
}

void runImages(const Options& options, const std::vector<Variant>& variants) {
    if (!fs::is_directory(options.out)) {
        throw std::runtime_error(options.out.string() + ": not a folder (create it, or pass --out DIR)");
    }
    // The runs' full-size PNGs and the synthetic EXR: kept in --keep DIR, else in a temporary folder removed
    // however this function ends.
    struct WorkDir {
        fs::path path;
        bool keep;
        explicit WorkDir(const fs::path& kept)
            : path(kept.empty() ? fs::temp_directory_path() / ("photopic-looks-" + std::to_string(getpid()))
                                : kept)
            , keep(!kept.empty()) {
            fs::create_directories(path);
        }
        WorkDir(const WorkDir&) = delete;
        WorkDir& operator=(const WorkDir&) = delete;
        ~WorkDir() {
            std::error_code ignored;
            if (!keep) {
                fs::remove_all(path, ignored);
            }
        }
    } const work(options.keep);
    const fs::path& workDir = work.path;
    const CliRun run{options.cli, workDir};
    const std::vector<TestImage> images = testImages(options, workDir);
    std::vector<std::vector<ClipShare>> fixed, automatic;
    for (const TestImage& image : images) {
        ImageFigures figures = measureImage(options, run, image, variants);
        fixed.push_back(std::move(figures.fixed));
        automatic.push_back(std::move(figures.automatic));
    }
    printClipTable("Fixed exposure (stills default, 0 EV)", variants, images, fixed);
    printClipTable("Auto exposure (autoExposure.enabled=true)", variants, images, automatic);
}

} // namespace

int main(int argc, char** argv) {
    try {
        const Options options = parseOptions(argc, argv);
        checkOklab();
        const std::vector<Variant> variants = allVariants();
        printHueTable("Test colours", variants, testColours());
        printHueTable("Pure primaries and ColorChecker patches", variants, referenceColours());
        printMidTable(variants);
        printChromaTable(variants);
        printRangeTable(variants);
        if (!options.hueOnly) {
            runImages(options, variants);
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
