// SPDX-License-Identifier: MIT
#pragma once
// A visibility module for tests of the debug views: it culls nothing and, when given a
// core::DebugRecord, appends a fixed description of its "query" (one occluded node, one occluder
// and an eye cell, at places the test chooses) without clearing the record first, so a test also
// sees whether the caller clears it between queries.
#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/module/VisibilityModule.h>

#include <string>

namespace osgVis::test
{
struct RecordedScene
{
    core::Aabb node;                  // recorded as NodeState::Invisible
    std::vector<core::Vec3> occluder; // recorded as the one active occluder
    core::Aabb eyeCell;
};

class RecordingTestModule : public core::VisibilityModule
{
public:
    static constexpr const char* Name = "test-recorder";

    explicit RecordingTestModule(RecordedScene recorded) : _recorded(std::move(recorded)) {}
    const char* name() const override { return Name; }
    void setScene(const core::Scene& scene) override { _scene = &scene; }
    void cull(const core::View&, core::VisibleSet&) override
    {
        if (!_record)
            return;
        _record->nodes.push_back({_recorded.node, core::NodeState::Invisible, 1});
        _record->activeOccluders.push_back(_recorded.occluder);
        _record->eyeCell = _recorded.eyeCell;
    }
    void setDebugRecord(core::DebugRecord* record) override { _record = record; }

private:
    RecordedScene _recorded;
    core::DebugRecord* _record = nullptr;
};

// Registers (or re-registers) the module under RecordingTestModule::Name, recording `recorded`.
inline void registerRecordingTestModule(const RecordedScene& recorded)
{
    core::registerModule(RecordingTestModule::Name,
                         [recorded] { return std::make_unique<RecordingTestModule>(recorded); });
}
} // namespace osgVis::test
