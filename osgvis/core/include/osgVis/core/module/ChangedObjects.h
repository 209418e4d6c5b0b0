// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Which objects changed since a module built its structure over the scene, for modules that answer
/// a change in time that grows with it (octree, frustum, cdt; docs/changes.md): a moved or inserted
/// object leaves the built structure's answer, whose boxes no longer hold it, and is tested on its
/// own; once too many changed, the module rebuilds.
#include <osgVis/core/module/VisibilityModule.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace osgVis::core
{
class ChangedObjects
{
public:
    /// Nothing changed; `objectCount` objects were built from.
    void reset(std::size_t objectCount)
    {
        _state.assign(objectCount, Unchanged);
        _moved.clear();
        _count = 0;
    }
    /// Takes a batch of changes; `onFirst(id)` for each object changed for the first time since
    /// reset, `onEach(id)` for every object named. False when the module should rebuild instead:
    /// fewer objects than before, or more than max(64, a quarter of them) changed since reset.
    template <class OnFirst, class OnEach>
    bool apply(std::size_t objectCount, const std::vector<SceneChange>& changes, OnFirst onFirst, OnEach onEach)
    {
        if (objectCount < _state.size())
            return false;
        _state.resize(objectCount, Unchanged);
        for (const SceneChange& change : changes)
            for (ObjectId id : change.objects)
            {
                if (id >= objectCount)
                    continue;
                if (_state[id] == Unchanged)
                {
                    ++_count;
                    onFirst(id);
                }
                const bool removed = change.kind == SceneChange::Kind::Removed;
                if (!removed && _state[id] != Moved)
                    _moved.push_back(id);
                _state[id] = removed ? Removed : Moved;
                onEach(id);
            }
        _moved.erase(std::remove_if(_moved.begin(), _moved.end(), [&](ObjectId id) { return _state[id] != Moved; }),
                     _moved.end());
        return _count <= std::max<std::size_t>(64, objectCount / 4);
    }
    bool changed(ObjectId id) const { return id < _state.size() && _state[id] != Unchanged; }
    /// Objects moved or inserted since reset and not removed since: drawn where the structure does not say.
    const std::vector<ObjectId>& moved() const { return _moved; }
    /// Objects changed since reset.
    std::size_t count() const { return _count; }

private:
    enum : std::uint8_t
    {
        Unchanged,
        Moved,
        Removed
    };
    std::vector<std::uint8_t> _state; // per object
    std::vector<ObjectId> _moved;
    std::size_t _count = 0;
};
} // namespace osgVis::core
