// Replays every committed fuzz input -- fuzz/corpus/<target>/ and the reproducers in tests/data/fuzz-repro/
// -- through the same entry points the libFuzzer harnesses call, with the normal compiler. A reader that
// crashes, throws something other than its documented error or breaks a checked promise fails the test (an
// abort ends the binary, which CTest reports as a failure naming the test).

#include "FuzzTargets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Target {
    const char* name;
    void (*run)(const std::uint8_t*, std::size_t);
};

constexpr Target kTargets[] = {
    {"settings", photopic::fuzz::settingsJson}, {"override", photopic::fuzz::settingsOverride},
    {"motion", photopic::fuzz::motionCsv},      {"camera", photopic::fuzz::cameraJson},
#ifdef PHOTOPIC_FUZZ_WITH_IO
    {"exr", photopic::fuzz::exrImage},          {"exrframe", photopic::fuzz::exrFrame},
    {"hdr", photopic::fuzz::hdrImage},          {"png", photopic::fuzz::pngImage},
#endif
#ifdef PHOTOPIC_FUZZ_WITH_SCENES
    {"gltf", photopic::fuzz::gltfModel},
#endif
};

/// The reproducers, each with the target whose reader misbehaved on it.
struct Reproducer {
    const char* file;
    const char* target;
};
constexpr Reproducer kReproducers[] = {
    {"settings_1e400.json", "settings"},
    {"override_invalid_utf8.txt", "override"},
    {"motion_nan_time.csv", "motion"},
    {"motion_lerp_overflow.csv", "motion"},
    {"settings_nested_70000.json", "settings"},
    {"override_nested_70000.txt", "override"},
#ifdef PHOTOPIC_FUZZ_WITH_IO
    {"png_zero_len_idat.min.png", "png"},
    {"png_flat_rgb_1000x1000.png", "png"},
    {"png_white_1bit_1024x1024.png", "png"},
    {"exr_deep_truncated.exr", "exr"},
    {"exr_deep_truncated.exr", "exrframe"},
    {"exrframe_channels_untyped.min.exr", "exrframe"},
    {"exrframe_chlist_overruns_size.min.exr", "exrframe"},
    {"exrframe_stored_chunk_short.exr", "exrframe"},
    {"exrframe_crop_overflows_camera.exr", "exrframe"},
    {"exrframe_channels_twice.exr", "exrframe"},
#endif
};

void PrintTo(const Target& target, std::ostream* os) {
    *os << target.name;
}
void PrintTo(const Reproducer& reproducer, std::ostream* os) {
    *os << reproducer.file;
}

std::vector<std::uint8_t> readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void replay(const Target& target, const fs::path& file) {
    SCOPED_TRACE(file.string());
    const std::vector<std::uint8_t> bytes = readFile(file);
    target.run(bytes.data(), bytes.size());
}

const Target& targetNamed(std::string_view name) {
    return *std::find_if(std::begin(kTargets), std::end(kTargets),
                         [&](const Target& t) { return name == t.name; });
}

class FuzzCorpus : public testing::TestWithParam<Target> {};

TEST_P(FuzzCorpus, EveryFileIsHandled) {
    const fs::path folder = fs::path(PHOTOPIC_SOURCE_DIR) / "fuzz" / "corpus" / GetParam().name;
    ASSERT_TRUE(fs::is_directory(folder)) << folder;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.is_regular_file()) {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    EXPECT_FALSE(files.empty()) << "no corpus in " << folder;
    for (const fs::path& file : files) {
        replay(GetParam(), file);
    }
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzCorpus, testing::ValuesIn(kTargets),
                         [](const testing::TestParamInfo<Target>& info) {
                             return std::string(info.param.name);
                         });

class FuzzReproducer : public testing::TestWithParam<Reproducer> {};

TEST_P(FuzzReproducer, IsHandled) {
    const fs::path file = fs::path(PHOTOPIC_SOURCE_DIR) / "tests" / "data" / "fuzz-repro" / GetParam().file;
    ASSERT_TRUE(fs::is_regular_file(file)) << file;
    replay(targetNamed(GetParam().target), file);
}

INSTANTIATE_TEST_SUITE_P(Files, FuzzReproducer, testing::ValuesIn(kReproducers),
                         [](const testing::TestParamInfo<Reproducer>& info) {
                             // The target too: one file may be a reproducer for two readers.
                             std::string name = std::string(info.param.target) + "_" + info.param.file;
                             std::replace_if(
                                 name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
                             return name;
                         });

} // namespace
