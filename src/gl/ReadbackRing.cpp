#include "gl/ReadbackRing.h"

#include <algorithm>
#include <string>

namespace photopic {

ReadbackRing::ReadbackRing(std::size_t bytes, int slots, std::string_view debugName)
    : mBytes(bytes) {
    mSlots.resize(std::size_t(std::max(slots, 1)));
    int i = 0;
    for (auto& slot : mSlots) {
        const std::string name = std::string(debugName) + " readback " + std::to_string(i++);
        const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        slot.buffer = Buffer({.size = bytes, .flags = flags, .data = nullptr, .debugName = name});
        slot.mapped = slot.buffer.mapPersistently(flags, "the read-back buffer '" + name + "'");
    }
}

bool ReadbackRing::enqueue(const Buffer& source, std::size_t offset, std::uint64_t tag) {
    auto it = std::find_if(mSlots.begin(), mSlots.end(), [](const Slot& s) { return !s.busy; });
    if (it == mSlots.end()) {
        ++mDropped;
        return false;
    }
    glCopyNamedBufferSubData(source.id(), it->buffer.id(), GLintptr(offset), 0, GLsizeiptr(mBytes));
    // Persistent coherent mapping: the copy's writes become visible to the client once the fence signals.
    glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
    it->fence = Fence::insert();
    // Flushed so the fence signals on its own: a non-blocking status query never flushes, and without it a
    // driver may hold the copy until something else submits (llvmpipe does).
    glFlush();
    it->tag = tag;
    it->order = mOrder++;
    it->busy = true;
    return true;
}

std::vector<ReadbackRing::Result> ReadbackRing::collect(bool wait, bool newestOnly) {
    std::vector<Slot*> ready;
    if (!wait && mReadyOverride && !mReadyOverride()) {
        return {};
    }
    for (auto& slot : mSlots) {
        if (!slot.busy) {
            continue;
        }
        if (wait) {
            slot.fence.wait();
        }
        if (wait || slot.fence.signalled()) {
            ready.push_back(&slot);
        }
    }
    std::sort(ready.begin(), ready.end(), [](const Slot* a, const Slot* b) { return a->order < b->order; });
    std::vector<Result> out;
    for (std::size_t i = 0; i < ready.size(); ++i) {
        Slot* slot = ready[i];
        slot->busy = false;
        if (!newestOnly || i + 1 == ready.size()) {
            out.push_back({slot->tag, {slot->mapped, mBytes}});
        }
    }
    return out;
}

ReadbackRing::Slot* ReadbackRing::oldestFinished() noexcept {
    Slot* oldest = nullptr;
    for (auto& slot : mSlots) {
        if (slot.busy && (!oldest || slot.order < oldest->order)) {
            oldest = &slot;
        }
    }
    return oldest && oldest->fence.signalled() ? oldest : nullptr;
}

std::optional<ReadbackRing::Result> ReadbackRing::pollNewest() {
    auto all = collect(false, true);
    if (all.empty()) {
        return std::nullopt;
    }
    return all.back();
}

std::vector<ReadbackRing::Result> ReadbackRing::pollAll() {
    return collect(false, false);
}
std::vector<ReadbackRing::Result> ReadbackRing::drain() {
    return collect(true, false);
}

int ReadbackRing::inFlight() const {
    return int(std::count_if(mSlots.begin(), mSlots.end(), [](const Slot& s) { return s.busy; }));
}

} // namespace photopic
