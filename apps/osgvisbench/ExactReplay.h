// SPDX-License-Identifier: MIT
#pragma once
// The `exact` mode: a visibility module that answers the oracle's visible set of the view being
// rendered, run through the same osgVis::VisibilityGroup as every module chain. It marks the
// frame-rate limit of culling (nothing drawn that is not seen) with the adapter's per-frame cost
// included, so a module's fps can be read against it. Bench-only: it knows the answer in advance.
#include "OracleReference.h"

#include <memory>

namespace osgVis::bench
{
class ExactReplay
{
public:
    // Registers the replay module in the core registry under `moduleName()`; call once, after the
    // command line's modes are validated (so no user can ask for it by name).
    explicit ExactReplay(const OracleReference& reference);

    static const char* moduleName() { return "bench-exact-replay"; }
    // The view whose exact set the next cull answers (the bench renders single-threaded).
    void setCurrentView(std::size_t view);
    // Queries whose visible set did not match the scene size: the VisibilityGroup numbered objects
    // differently from the bench's extraction, and kept them all rather than guess.
    std::size_t mismatchedQueries() const;

    struct State;

private:
    std::shared_ptr<State> _state;
};
} // namespace osgVis::bench
