#pragma once
// Non-blocking GPU -> CPU readback (a CPU reader never stalls the GPU): N slots, each a persistently mapped
// buffer and a fence. The GPU copies into a free slot; the CPU takes the newest slot whose fence has
// signalled. When nothing new has finished, the caller keeps its last result, so a display of it never drops
// to empty. The frame path never waits.

#include "gl/Objects.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace photopic {

class ReadbackRing {
public:
    ReadbackRing() = default;
    /// `slots` buffers of `bytes` each.
    ReadbackRing(std::size_t bytes, int slots, std::string_view debugName);

    /// Copies `bytes` of `source` at `offset` into a free slot, tagged with `tag` (the frame index), and
    /// fences. Returns false (nothing queued, `dropped()` counts it) when every slot is still in flight.
    bool enqueue(const Buffer& source, std::size_t offset, std::uint64_t tag);

    struct Result {
        std::uint64_t tag = 0;
        std::span<const std::byte> bytes;
    };
    /// The newest finished slot not yet returned, or nothing. Older finished slots are released
    /// (non-blocking).
    std::optional<Result> pollNewest();
    /// Every finished slot not yet returned, oldest first (non-blocking). For consumers that need each frame.
    std::vector<Result> pollAll();
    /// Hands every finished slot not yet returned to `visit(const Result&)`, oldest first, without allocating
    /// (non-blocking; the bytes are valid during the call). Returns how many. For per-frame consumers that
    /// must not allocate (the pipeline's subject probes).
    template <class Visit>
    int pollEach(Visit&& visit) {
        if (mReadyOverride && !mReadyOverride()) {
            return 0;
        }
        int n = 0;
        while (Slot* slot = oldestFinished()) {
            slot->busy = false;
            visit(Result{slot->tag, {slot->mapped, mBytes}});
            ++n;
        }
        return n;
    }
    /// Blocks until every slot in flight has finished and returns them oldest first (end of an offline
    /// sequence).
    std::vector<Result> drain();

    /// Test hook (for the continuity test): while set, a non-blocking poll also needs `ready()` to return
    /// true before it takes a signalled slot, so a test can hold results "in flight". drain() ignores it.
    void setReadyOverride(std::function<bool()> ready) { mReadyOverride = std::move(ready); }

    [[nodiscard]] int inFlight() const;
    [[nodiscard]] std::uint64_t dropped() const { return mDropped; }
    /// True when every slot is in flight: the next enqueue() would be dropped.
    [[nodiscard]] bool full() const {
        return std::all_of(mSlots.begin(), mSlots.end(), [](const Slot& s) { return s.busy; });
    }
    [[nodiscard]] int slotCount() const { return int(mSlots.size()); }

private:
    struct Slot {
        Buffer buffer;
        const std::byte* mapped = nullptr;
        Fence fence;
        std::uint64_t tag = 0;
        std::uint64_t order = 0;
        bool busy = false;
    };
    std::vector<Result> collect(bool wait, bool newestOnly);
    /// The busy slot enqueued first, when its fence has signalled (fences signal in submission order).
    Slot* oldestFinished() noexcept;

    std::vector<Slot> mSlots;
    std::size_t mBytes = 0;
    std::uint64_t mOrder = 0;
    std::uint64_t mDropped = 0;
    std::function<bool()> mReadyOverride;
};

} // namespace photopic
