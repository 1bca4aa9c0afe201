#pragma once
// The fuzz targets' entry points, one per reader a user's file reaches. The libFuzzer harnesses (fuzz_*.cpp)
// call them, and so does the regression test that replays the committed corpus (test_fuzz_corpus.cpp) in
// every ordinary build, so a corpus file means the same thing in both.
//
// Each entry point feeds the bytes to the reader and swallows only the error the reader documents for bad
// input (IoError, SettingsError, MotionError, ModelError, the CLI's InputError; std::invalid_argument from
// cameraFromExr). Anything else -- another exception, a crash, a sanitizer report -- is a finding. Where the
// reader promises more than "no crash" (finite motion, a settings round-trip, layers of the colour's size, a
// valid camera, the same frame whatever storage a sequence reader kept, no file read outside a model's
// folder, every PNG that libpng reads read), the entry point checks that too and aborts when it does not
// hold.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace photopic::fuzz {

void settingsJson(const std::uint8_t* data, std::size_t size);     ///< readSettingsJson, then save and reload
void settingsOverride(const std::uint8_t* data, std::size_t size); ///< applySettingsOverride per line
void motionCsv(const std::uint8_t* data, std::size_t size);        ///< parseMotionCsv, then at() everywhere
void exrImage(const std::uint8_t* data, std::size_t size);         ///< decodeImage on OpenEXR bytes
/// decodeExrFrame (layers, camera attributes, cameraFromExr), and the sequence reader into kept storage
void exrFrame(const std::uint8_t* data, std::size_t size);
void hdrImage(const std::uint8_t* data, std::size_t size); ///< decodeImage on Radiance bytes
/// decodeImage and decodePng8 on PNG bytes; a file they refuse must be one libpng refuses too
void pngImage(const std::uint8_t* data, std::size_t size);
/// loadModelFromMemory on GLB or glTF bytes, with no base folder and with a sandbox's model folder (a file
/// read outside it aborts)
void gltfModel(const std::uint8_t* data, std::size_t size);
void cameraJson(const std::uint8_t* data, std::size_t size); ///< parseCameraTrack (`photopic image --camera`)

// To add a target (say `cube`, a LUT reader in the io library): declare its entry point here (cubeLut) and
// define it in FuzzTargetsCore.cpp (no GL, no image IO), FuzzTargetsIo.cpp, FuzzTargetsScenes.cpp or
// FuzzTargetsCli.cpp (the CLI's GL-free sources, compiled in); add fuzz_cube.cpp (like the others), the name
// to the list of its library in fuzz/CMakeLists.txt (PHOTOPIC_FUZZ_IO_TARGETS), {"cube", cubeLut} to the
// table in test_fuzz_corpus.cpp and cube to FUZZ_TARGETS in the Makefile; commit a few small valid inputs as
// fuzz/corpus/cube/, and each reproducer the fuzzer finds to tests/data/fuzz-repro/ (listed in
// test_fuzz_corpus.cpp's kReproducers and tests/data/SOURCES.md).

} // namespace photopic::fuzz
