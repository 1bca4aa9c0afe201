// Test fixture for farm.sh: how far a chunked run's display frames are from the single run's. Reads two
// folders of PNGs with the same names and prints, per frame and in all, the mean and the largest difference
// in code values over the RGB channels and the share of pixels that differ by more than 2 in any channel.
//
//   photopic_farm_fixture SINGLE_DIR CHUNKED_DIR
//
// Output lines: "frame NAME mean M max X over2 P" per file of SINGLE_DIR (in name order), then
// "all mean M max X worstmean W worstframe NAME". A file missing from CHUNKED_DIR or of another size is an
// error (exit 1).

#include "FixtureMain.h"
#include "io/ImageIO.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

int run(const fs::path& single, const fs::path& chunked) {
    std::vector<fs::path> names;
    for (const auto& entry : fs::directory_iterator(single)) {
        if (entry.path().extension() == ".png") {
            names.push_back(entry.path().filename());
        }
    }
    std::sort(names.begin(), names.end());
    if (names.empty()) {
        throw std::runtime_error(single.string() + " holds no PNG");
    }
    double sumAll = 0.0;
    double countAll = 0.0;
    int maxAll = 0;
    double worstMean = -1.0;
    std::string worstName;
    for (const fs::path& name : names) {
        const photopic::Image8 a = photopic::readPng8(single / name);
        const photopic::Image8 b = photopic::readPng8(chunked / name);
        if (a.width != b.width || a.height != b.height) {
            throw std::runtime_error(name.string() + ": the two frames differ in size");
        }
        double sum = 0.0;
        int maxDiff = 0;
        std::size_t over = 0;
        const std::size_t pixels = std::size_t(a.width) * std::size_t(a.height);
        for (std::size_t p = 0; p < pixels; ++p) {
            int pixelMax = 0;
            for (int c = 0; c < 3; ++c) {
                const std::size_t i = p * 4 + std::size_t(c);
                const int d = std::abs(int(a.rgba[i]) - int(b.rgba[i]));
                sum += d;
                pixelMax = std::max(pixelMax, d);
            }
            maxDiff = std::max(maxDiff, pixelMax);
            over += pixelMax > 2 ? 1 : 0;
        }
        const double mean = sum / (3.0 * double(pixels));
        std::printf("frame %s mean %.4f max %d over2 %.4f\n", name.string().c_str(), mean, maxDiff,
                    double(over) / double(pixels));
        sumAll += sum;
        countAll += 3.0 * double(pixels);
        maxAll = std::max(maxAll, maxDiff);
        if (mean > worstMean) {
            worstMean = mean;
            worstName = name.string();
        }
    }
    std::printf("all mean %.4f max %d worstmean %.4f worstframe %s\n", sumAll / countAll, maxAll, worstMean,
                worstName.c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return photopic::test::fixtureMain(argc, argv, 2, "SINGLE_DIR CHUNKED_DIR",
                                       [&] { return run(argv[1], argv[2]); });
}
