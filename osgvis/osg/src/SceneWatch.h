// SPDX-License-Identifier: MIT
#pragma once
// Internal: how a ViewCuller finds, at each cull, that the subgraph it extracted has changed although
// nobody called dirtyScene(). OSG tells no one about changes, so right after an extraction the watch
// records everything the extraction read (per node: children and their masks, the children an active
// traversal enters, culling-active flags, matrices, state, drawables' bounds and geometry counters),
// and each cull compares it again in flat arrays (docs/changes.md lists what is watched and why).
#include <osg/BoundingBox>
#include <osg/Geometry>
#include <osg/Matrixd>
#include <osg/Node>
#include <osg/ref_ptr>

#include <cstdint>
#include <vector>

namespace osgVis
{
class SceneWatch
{
public:
    /// Records `root`'s subgraph as the extractor traverses it: active children, a paged node's
    /// children as loaded (the count of those is ExtractedScene::pagedNodesChanged's to watch).
    void record(osg::Node& root);
    /// What reads differently now than recorded.
    struct Difference
    {
        bool other = false;                  ///< anything but a transform's matrix
        std::vector<const osg::Node*> moved; ///< transforms whose matrix changed (all of them when !other)
        std::vector<std::uint32_t> movedEntries;
        bool any() const { return other || !moved.empty(); }
    };
    /// Compares, stopping at the first difference that is not a matrix; the answer is valid until
    /// the next call. Not thread-safe: one caller at a time (it also notes callbacks osgVis
    /// installed since the recording).
    const Difference& compare() const;
    /// True when something recorded reads differently now; false when nothing is recorded.
    bool changed() const;
    /// Takes the moved transforms' matrices as recorded, once the objects below them are placed again.
    void acceptMatrices(const Difference& difference);
    void clear();
    /// What is watched, for statistics and benchmarks.
    std::size_t nodeCount() const { return _nodes.size(); }
    /// State sets whose values are compared, and objects held (recorded, and taken on since by
    /// nodes that swapped to an equal state set): bounded by what was recorded, for tests.
    std::size_t stateEntries() const { return _states.size() + _adopted.size(); }
    std::size_t heldEntries() const { return _held.size() + 2 * _adopted.size(); }

private:
    friend class SceneWatchRecorder;
    static constexpr std::uint32_t None = ~0u;
    static constexpr std::uint64_t NoState = 0;

    struct NodeEntry
    {
        const osg::Node* node;
        mutable const osg::StateSet* stateSet; ///< the last one found (an equal one may replace it)
        std::uint64_t stateKey;                ///< drawnStateKey of the recorded one (NoState: none)
        const osg::Callback* cullCallback;     ///< the application's, below osgVis's own
        /// The callback last found on the node that leads to cullCallback (osgVis's own installs
        /// after the recording): compared first, as a pointer.
        mutable const osg::Callback* seenCallback;
        /// Its slot in _adopted once it swapped state set or callback since the recording (None before).
        mutable std::uint32_t adopted;
        bool cullingActive;                   ///< getCullingActive(): what lies below a node without it is never culled
        bool listsChildren;                   ///< a group's children are listed; a paged node's are not (the pager's)
        std::uint32_t firstChild, childCount; ///< in _children
        std::uint32_t transform, drawable;    ///< in _transforms, _drawables, or None
    };
    struct ChildEntry
    {
        const osg::Node* child;
        osg::Node::NodeMask mask;
    };
    /// A group whose cull traversal may enter only some of its children (Switch, LOD, Sequence, any
    /// type the kit does not know): the children an active traversal entered.
    struct SelectionEntry
    {
        osg::Group* group;
        std::uint32_t first, count; ///< in _selected
    };
    struct TransformEntry
    {
        osg::Matrixd matrix; ///< local to parent
    };
    struct DrawableEntry
    {
        osg::BoundingBox box;
        const osg::Geometry* geometry; ///< the drawable as a Geometry (null when it is none)
        bool drawArrays;               ///< some primitive set is a DrawArrays
        std::uint64_t geometryKey;     ///< arrays, primitive sets, their modified counts, callbacks
    };
    struct KeyEntry
    {
        const osg::Referenced* object; ///< a state set or an osgVis marker node
        std::uint64_t key;
    };
    /// What one node took on since the recording, held: its state set now (equal to the recorded
    /// one for the extraction, its values watched from then on) and the callback last seen on it.
    struct AdoptedEntry
    {
        osg::ref_ptr<const osg::StateSet> stateSet;
        std::uint64_t key; ///< the state set's drawnStateKey when it was taken on
        osg::ref_ptr<const osg::Callback> callback;
    };

    enum class Reading
    {
        Same,
        Moved, ///< only the matrix differs
        Other
    };
    Reading read(const NodeEntry& entry) const;
    AdoptedEntry& adopted(const NodeEntry& entry) const;
    bool statesChanged() const;

    std::vector<NodeEntry> _nodes;
    std::vector<ChildEntry> _children;
    std::vector<SelectionEntry> _selections;
    std::vector<const osg::Node*> _selected;
    std::vector<TransformEntry> _transforms;
    std::vector<DrawableEntry> _drawables;
    std::vector<KeyEntry> _states; ///< each distinct recorded state set's values
    std::vector<KeyEntry> _markers;
    /// Everything above is held, so that no address compared is ever reused by a new object.
    std::vector<osg::ref_ptr<const osg::Referenced>> _held;
    /// One slot per node that swapped since the recording, replaced at each swap: an application
    /// toggling between two state sets (a highlight) would otherwise grow the watch every frame. What
    /// a slot lets go of is compared by no one any more (the node's entry points to the new object).
    mutable std::vector<AdoptedEntry> _adopted;
    mutable Difference _difference; ///< compare's answer, kept so that a warm compare allocates nothing
};
} // namespace osgVis
