#include "gl/GpuTimers.h"

namespace photopic {

Query& GpuTimers::queryAt(std::vector<Query>& queries, int index) {
    while (int(queries.size()) <= index) {
        queries.emplace_back(GL_TIMESTAMP);
    }
    return queries[std::size_t(index)];
}

void GpuTimers::beginFrame() {
    if (!mEnabled) {
        mOpen = false;
        return;
    }
    Slot& slot = mSlots[std::size_t(mCurrent)];
    if (slot.pending) {
        // The ring is full: harvest if ready; if not, this frame's slot is reused and its old results dropped
        // rather than waiting on the GPU.
        if (!harvest(slot, false)) {
            slot.pending = false;
        }
    }
    slot.used = 0;
    slot.names.clear();
    slot.bytes.clear();
    slot.wallMs.clear();
    mOpen = true;
    // Opportunistically harvest older frames that have completed.
    for (auto& other : mSlots) {
        if (other.pending && &other != &slot) {
            harvest(other, false);
        }
    }
}

void GpuTimers::begin(std::string_view name, double bytesMoved) {
    if (!mOpen) {
        return;
    }
    Slot& slot = mSlots[std::size_t(mCurrent)];
    if (mSynchronous) {
        glFinish(); // the previous passes' deferred work lands before this pass's bracket opens
        mWallStart = std::chrono::steady_clock::now();
    }
    glQueryCounter(queryAt(slot.starts, slot.used).id(), GL_TIMESTAMP);
    slot.names.emplace_back(name);
    slot.bytes.push_back(bytesMoved);
}

void GpuTimers::end() {
    if (!mOpen) {
        return;
    }
    Slot& slot = mSlots[std::size_t(mCurrent)];
    glQueryCounter(queryAt(slot.ends, slot.used).id(), GL_TIMESTAMP);
    if (mSynchronous) {
        glFinish();
        slot.wallMs.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - mWallStart).count());
    } else {
        slot.wallMs.push_back(-1);
    }
    ++slot.used;
}

void GpuTimers::endFrame() {
    if (!mOpen) {
        return;
    }
    Slot& slot = mSlots[std::size_t(mCurrent)];
    slot.frame = mFrameCounter++;
    slot.pending = slot.used > 0;
    mCurrent = (mCurrent + 1) % kFramesInFlight;
    mOpen = false;
}

bool GpuTimers::harvest(Slot& slot, bool wait) {
    if (!slot.pending || slot.used == 0) {
        return false;
    }
    if (!wait) {
        GLint available = GL_FALSE;
        glGetQueryObjectiv(slot.ends[std::size_t(slot.used - 1)].id(), GL_QUERY_RESULT_AVAILABLE, &available);
        if (available != GL_TRUE) {
            return false;
        }
    }
    std::vector<PassTiming> result;
    result.reserve(std::size_t(slot.used));
    for (int i = 0; i < slot.used; ++i) {
        GLuint64 t0 = 0, t1 = 0;
        glGetQueryObjectui64v(slot.starts[std::size_t(i)].id(), GL_QUERY_RESULT, &t0);
        glGetQueryObjectui64v(slot.ends[std::size_t(i)].id(), GL_QUERY_RESULT, &t1);
        result.push_back({slot.names[std::size_t(i)], t1 > t0 ? double(t1 - t0) * 1e-6 : 0.0,
                          slot.bytes[std::size_t(i)], slot.wallMs[std::size_t(i)]});
    }
    slot.pending = false;
    if (slot.frame > mLatestFrame) {
        mLatestFrame = slot.frame;
        mLatest = result;
    }
    mHarvested.push_back(std::move(result));
    if (mHarvested.size() > kKeptFrames) {
        mHarvested.erase(mHarvested.begin());
    }
    return true;
}

std::vector<std::vector<PassTiming>> GpuTimers::drain() {
    // Oldest first: slots after the current one were written earlier.
    for (int i = 0; i < kFramesInFlight; ++i) {
        harvest(mSlots[std::size_t((mCurrent + i) % kFramesInFlight)], true);
    }
    return std::exchange(mHarvested, {});
}

std::vector<std::vector<PassTiming>> GpuTimers::collect() {
    // Oldest first, stopping at the first frame still in flight so the order holds.
    for (int i = 0; i < kFramesInFlight; ++i) {
        Slot& slot = mSlots[std::size_t((mCurrent + i) % kFramesInFlight)];
        if (slot.pending && !harvest(slot, false)) {
            break;
        }
    }
    return std::exchange(mHarvested, {});
}

} // namespace photopic
