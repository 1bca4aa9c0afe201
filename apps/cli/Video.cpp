#include "Video.h"

#include "io/ImageIO.h"

#include <fmt/format.h>

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <cerrno>
#include <cstring>
#include <optional>
#include <vector>

extern char** environ;

namespace photopic::cli {

namespace fs = std::filesystem;

namespace {

/// ffmpeg's image-sequence input reads '%' as the start of a pattern: a literal one is written "%%".
std::string escapePercent(const std::string& text) {
    std::string out;
    for (char c : text) {
        out += c == '%' ? std::string("%%") : std::string(1, c);
    }
    return out;
}

} // namespace

/// Runs `args` (args[0] found on PATH) and waits. Returns the exit status, or -ENOENT-style negative errno
/// when it could not be started.
int runProgram(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) {
        argv.push_back(const_cast<char*>(a.c_str()));
    }
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
        return -spawned;
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            return -errno;
        }
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}


VideoResult encodeFrameSequence(const fs::path& folder, double fps, const fs::path& output) {
    // Absolute paths: a name starting with '-' could read as an option, one like "x:y" as a protocol.
    const fs::path target = fs::absolute(output);
    // ffmpeg writes into the io library's atomic file (a temporary beside the target), which commit() then
    // flushes to disk and renames into place; on any failure the writer removes it.
    std::optional<AtomicFileWriter> file;
    try {
        file.emplace(target);
    } catch (const IoError& e) {
        return {false, fmt::format("{} FAILED ({})", output.filename().string(), e.what())};
    }
    const fs::path temporary = file->temporaryPath().empty() ? target : file->temporaryPath();
    const std::vector<std::string> args = {"ffmpeg",
                                           "-nostdin",
                                           "-y",
                                           "-loglevel",
                                           "error",
                                           "-framerate",
                                           fmt::format("{:.6g}", fps),
                                           "-i",
                                           escapePercent(fs::absolute(folder).string()) + "/frame_%04d.png",
                                           "-pix_fmt",
                                           "yuv420p",
                                           "-vf",
                                           "scale=trunc(iw/2)*2:trunc(ih/2)*2",
                                           "-f",
                                           "mp4",
                                           temporary.string()};
    const int status = runProgram(args);
    if (status == -ENOENT) {
        return {false, fmt::format("{} skipped (no ffmpeg command)", output.filename().string())};
    }
    if (status != 0) {
        return {false, status < 0 ? fmt::format("{} FAILED (cannot start ffmpeg: {})",
                                                output.filename().string(), std::strerror(-status))
                                  : fmt::format("{} FAILED (ffmpeg exited with {})",
                                                output.filename().string(), status)};
    }
    try {
        file->commit();
    } catch (const IoError& e) {
        return {false, fmt::format("{} FAILED ({})", output.filename().string(), e.what())};
    }
    return {true, output.filename().string()};
}

} // namespace photopic::cli
