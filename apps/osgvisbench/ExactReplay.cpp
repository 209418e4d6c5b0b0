// SPDX-License-Identifier: MIT
#include "ExactReplay.h"

#include <osgVis/core/api/ModuleRegistry.h>

namespace osgVis::bench
{
struct ExactReplay::State
{
    const OracleReference* reference = nullptr;
    std::size_t currentView = 0;
    std::size_t mismatchedQueries = 0;
};

namespace
{
class ExactReplayModule : public core::VisibilityModule
{
public:
    explicit ExactReplayModule(std::shared_ptr<ExactReplay::State> state) : _state(std::move(state)) {}

    const char* name() const override { return ExactReplay::moduleName(); }
    bool judgesSlivers() const override { return true; }
    void setScene(const core::Scene& scene) override { _scene = &scene; }

    // Never culls a visible object: keeps exactly the oracle's answer for the current view.
    void cull(const core::View&, core::VisibleSet& visible) override
    {
        const core::VisibleSet& exact = _state->reference->views.at(_state->currentView).exact;
        if (exact.capacity() != visible.capacity())
        {
            ++_state->mismatchedQueries;
            return;
        }
        visible.intersectWith(exact);
    }

private:
    std::shared_ptr<ExactReplay::State> _state;
};
} // namespace

ExactReplay::ExactReplay(const OracleReference& reference) : _state(std::make_shared<State>())
{
    _state->reference = &reference;
    std::shared_ptr<State> state = _state;
    core::registerModule(moduleName(), [state]() { return std::make_unique<ExactReplayModule>(state); });
}

void ExactReplay::setCurrentView(std::size_t view)
{
    _state->currentView = view;
}

std::size_t ExactReplay::mismatchedQueries() const
{
    return _state->mismatchedQueries;
}
} // namespace osgVis::bench
