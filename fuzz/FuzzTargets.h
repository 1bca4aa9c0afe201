#pragma once
// The fuzz targets' entry points, one per reader a user's file reaches. The libFuzzer harnesses (fuzz_*.cpp)
// call them, and so does the regression test that replays the committed corpus (test_fuzz_corpus.cpp) in
// every ordinary build, so a corpus file means the same thing in both.
//
// Each entry point feeds the bytes to the reader and swallows only the error the reader documents for bad
// input (IoError, SettingsError, MotionError, ModelError). Anything else -- another exception, a crash, a
// sanitizer report -- is a finding. Where the reader promises more than "no crash" (finite motion, a settings
// round-trip), the entry point checks that too and aborts when it does not hold.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace photopic::fuzz {

void settingsJson(const std::uint8_t* data, std::size_t size);     ///< readSettingsJson, then save and reload
void settingsOverride(const std::uint8_t* data, std::size_t size); ///< applySettingsOverride per line
void motionCsv(const std::uint8_t* data, std::size_t size);        ///< parseMotionCsv, then at() everywhere
void exrImage(const std::uint8_t* data, std::size_t size);         ///< decodeImage on OpenEXR bytes
void hdrImage(const std::uint8_t* data, std::size_t size);         ///< decodeImage on Radiance bytes
void pngImage(const std::uint8_t* data, std::size_t size);  ///< decodeImage and decodePng8 on PNG bytes
void gltfModel(const std::uint8_t* data, std::size_t size); ///< loadModelFromMemory on GLB or glTF bytes

// To add a target (camera JSON, EXR camera attributes): declare its entry point here and define it in
// FuzzTargetsCore.cpp (no GL, no image IO), FuzzTargetsIo.cpp or FuzzTargetsScenes.cpp; add fuzz_<name>.cpp
// (like the others) and the name to PHOTOPIC_FUZZ_TARGETS in fuzz/CMakeLists.txt, to the table in
// test_fuzz_corpus.cpp, and to FUZZ_TARGETS in the Makefile; commit a few valid inputs as
// fuzz/corpus/<name>/.

} // namespace photopic::fuzz
