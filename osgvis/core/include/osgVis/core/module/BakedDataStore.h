// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// A process-wide store of data baked for models, keyed by the model's fingerprint: a file reader
/// puts what it trusted, and any module later given a scene of that fingerprint finds it. One per
/// kind of data (cell-portal data, view cells, a level's own cells). Thread-safe.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>

namespace osgVis::core
{
template <class Data> class BakedDataStore
{
public:
    /// The store of this kind of data (a function-local static, so readers may register from
    /// static initializers in any order).
    static BakedDataStore& instance()
    {
        static BakedDataStore store;
        return store;
    }
    /// Replaces what was stored under `fingerprint`; null data are ignored.
    void put(std::uint64_t fingerprint, std::shared_ptr<const Data> data)
    {
        if (!data)
            return;
        const std::lock_guard<std::mutex> lock(_mutex);
        _byFingerprint[fingerprint] = std::move(data);
    }
    std::shared_ptr<const Data> find(std::uint64_t fingerprint) const
    {
        const std::lock_guard<std::mutex> lock(_mutex);
        const auto found = _byFingerprint.find(fingerprint);
        return found == _byFingerprint.end() ? nullptr : found->second;
    }

private:
    mutable std::mutex _mutex;
    std::map<std::uint64_t, std::shared_ptr<const Data>> _byFingerprint;
};
} // namespace osgVis::core
