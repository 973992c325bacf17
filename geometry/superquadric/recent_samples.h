#pragma once
// The last few points of a search and what was taken at them: a halved stretch shares its ends with its parent and
// its sibling, and the search asks about a point (its value, or a bound that uses it) after the point was taken.
#include <algorithm>

namespace isotrace {

template <class Sample, int kSize = 4>
class RecentSamples {
public:
    // The sample at t, taken by take() when t is not among the recent points.
    template <class Take>
    const Sample& at(double t, const Take& take) {
        if (const Sample* known = find(t)) return *known;
        Entry& slot = entries_[next_];
        slot = {t, take()};
        next_ = (next_ + 1) % kSize;
        filled_ = std::min(filled_ + 1, kSize);
        return slot.sample;
    }
    // The sample at t when it is among the recent points, else nullptr.
    const Sample* find(double t) const {
        for (int k = 0; k < filled_; ++k)
            if (entries_[k].t == t) return &entries_[k].sample;
        return nullptr;
    }

private:
    struct Entry {
        double t;
        Sample sample;
    };
    Entry entries_[kSize];
    int filled_ = 0, next_ = 0;
};

}  // namespace isotrace
