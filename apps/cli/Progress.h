#pragma once
// The progress line of long work: "scene canvas: 24/60 frames, 11.8 frames/s, ETA 3 s", redrawn in place on
// stderr. Drawn only when stderr is a terminal, only once the work has run for about a second (short work
// stays silent), never with -q; a pipe or a log file gets none of it.

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

namespace photopic::cli {

class Progress {
public:
    /// `total` items of `unit` ("frames", "images"); nothing is drawn yet.
    Progress(std::string label, std::size_t total, std::string unit = "frames");
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// One more item done (or `count`); redraws at most ten times a second.
    void advance(std::size_t count = 1);
    /// Takes the line off the terminal, so a line printed next starts clean; the next advance() redraws it.
    void clear();
    /// Shows "label: text" at once, until clear() or the next advance(): for a step that cannot count its
    /// work (an external encoder). Same rules: a terminal only, never with -q.
    void note(std::string_view text);

    /// -q turns every progress line off (main sets it once, before any command runs).
    static void setEnabled(bool enabled);

private:
    void draw();

    std::string mLabel;
    std::string mUnit;
    std::size_t mTotal;
    std::size_t mDone = 0;
    bool mTerminal;
    bool mShown = false;
    std::chrono::steady_clock::time_point mStart;
    std::chrono::steady_clock::time_point mLastDraw;
};

} // namespace photopic::cli
