// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// The visibility API between a renderer and a visibility algorithm: a scene description the module
/// keeps between frames, a view in, a visible set out, notification when the scene changes.
#include <osgVis/core/module/BakedData.h>
#include <osgVis/core/scene/DebugRecord.h>
#include <osgVis/core/scene/View.h>
#include <osgVis/core/scene/ViewRegion.h>
#include <osgVis/core/scene/VisibleSet.h>

#include <memory>
#include <vector>

namespace osgVis::core
{
struct SceneChange
{
    enum class Kind
    {
        Inserted, ///< objects appended to the scene
        Moved,    ///< bounds / triangles of objects changed
        Removed,  ///< objects no longer drawn (their ids stay valid but must not be reported)
    };
    Kind kind = Kind::Moved;
    std::vector<ObjectId> objects;
};

class VisibilityModule
{
public:
    virtual ~VisibilityModule() = default;
    virtual const char* name() const = 0;
    /// True when the module may cull visible objects (only modes named `approx`).
    virtual bool approximate() const { return false; }
    /// True when the answer already holds every object the view shows, slivers included (a replay of
    /// an oracle): ModuleChain then adds no OBJECT_SLIVERS object back.
    virtual bool judgesSlivers() const { return false; }

    /// Data baked for the model, from whoever holds it (a VisibilityGroup read from a .pvs): the
    /// module keeps the kinds it knows and uses them from the next setScene, when they fit the scene.
    /// The default takes none.
    virtual void setBakedData(const BakedData& baked) { (void)baked; }
    /// Build phase: may allocate and take long. The scene outlives the module or the next setScene.
    virtual void setScene(const Scene& scene) = 0;
    /// The scene (same object as given to setScene) changed; the default hands the change to
    /// sceneReplaced with that same scene (so a module that takes changes overrides that one only).
    virtual void sceneChanged(const SceneChange& change);
    /// The renderer re-extracted the scene into a new object (`scene`) in which every object kept its
    /// id; `changes` say which ids were inserted, moved or removed relative to the scene the module
    /// had. The module must use `scene` from now on; the default calls setScene(scene).
    virtual void sceneReplaced(const Scene& scene, const std::vector<SceneChange>& changes);

    /// Query phase. `visible` arrives holding the candidates (all objects, or what earlier modules
    /// of a chain kept) and leaves holding a subset of them.
    /// Guarantee (non-approximate modules): never culls a visible object; may keep hidden ones.
    virtual void cull(const View& view, VisibleSet& visible) = 0;

    /// Region queries (asynchronous visibility): true when cullRegion answers for a whole region of
    /// viewpoints. Modules that cannot keep the default: a chain with one of them has no region answer.
    virtual bool supportsRegions() const { return false; }
    /// Like cull, for every view `region` holds and in every direction: never culls an object that
    /// some such view sees (non-approximate modules). Called only when supportsRegions(); it may
    /// share per-frame state with cull, so the two are never called concurrently on one module.
    virtual void cullRegion(const ViewRegion& region, VisibleSet& visible) { (void)region, (void)visible; }
    /// Progressive region answers: pass 0 is the fastest, each later one at least as good, the
    /// last (regionPasses() - 1) what cullRegion answers. Every pass is conservative on its own,
    /// so a caller may use whichever finished last. The default has one pass: cullRegion.
    virtual std::uint32_t regionPasses() const { return 1; }
    virtual void cullRegionPass(const ViewRegion& region, VisibleSet& visible, std::uint32_t pass)
    {
        (void)pass;
        cullRegion(region, visible);
    }

    /// Debug views: when `record` is set, later queries describe their decisions into it (nullptr
    /// stops). Modules without a spatial structure leave it untouched.
    virtual void setDebugRecord(DebugRecord* record) { (void)record; }

protected:
    const Scene* _scene = nullptr;
};
} // namespace osgVis::core
