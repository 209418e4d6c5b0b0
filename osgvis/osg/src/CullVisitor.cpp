// SPDX-License-Identifier: MIT
#include <osgVis/CullVisitor>

#include <osgVis/core/api/ModuleRegistry.h>

#include "ClusterCulling.h"
#include "TreeCull.h"

#include <osg/Camera>
#include <osg/PagedLOD>
#include <osg/ProxyNode>
#include <osgUtil/RenderStage>
#include <osgUtil/SceneView>
#include <osgViewer/Renderer>
#include <osgViewer/View>

#include <functional>

namespace osgVis
{
CullVisitor::Shared::Shared(const std::string& modes)
{
    setModes(modes);
}

CullVisitor::Shared::~Shared() = default;

ViewCuller& CullVisitor::Shared::cullerFor(osg::Node& root)
{
    std::lock_guard<std::mutex> lock(_mutex);
    osg::ref_ptr<ViewCuller>& culler = _cullers[&root];
    if (!culler)
        culler = new ViewCuller(_modes);
    _latest = culler;
    return *culler;
}

void CullVisitor::Shared::setModes(const std::string& modes)
{
    core::createChain(modes); // validates: throws UnknownModeError
    std::lock_guard<std::mutex> lock(_mutex);
    _modes = modes;
    for (auto& entry : _cullers)
        entry.second->setModes(modes);
}

std::string CullVisitor::Shared::getModes() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _modes;
}

void CullVisitor::Shared::dirtyScene()
{
    std::lock_guard<std::mutex> lock(_mutex);
    for (auto& entry : _cullers)
        entry.second->dirtyScene();
}

CullStatistics CullVisitor::Shared::getLastStatistics() const
{
    std::lock_guard<std::mutex> lock(_mutex);
    return _latest ? _latest->getLastStatistics() : CullStatistics{};
}

CullVisitor::CullVisitor(const std::string& modes) : _shared(new Shared(modes)) {}

CullVisitor::CullVisitor(const CullVisitor& other)
    : osg::Object(other), osgUtil::CullVisitor(other), _shared(other._shared)
{
}

CullVisitor::~CullVisitor() = default;

void CullVisitor::setModes(const std::string& modes)
{
    _shared->setModes(modes);
}

std::string CullVisitor::getModes() const
{
    return _shared->getModes();
}

void CullVisitor::dirtyScene()
{
    _shared->dirtyScene();
}

CullStatistics CullVisitor::getLastStatistics() const
{
    return _shared->getLastStatistics();
}

void CullVisitor::reset()
{
    osgUtil::CullVisitor::reset();
    _activeRoot = nullptr;
    _active = {};
    _decided = false;
}

namespace
{
// The first matrix pushed, which SceneView sets to the camera's view (or projection).
// note: osg::fast_back_stack keeps the top in _value and the rest, bottom first, in _stack.
const osg::RefMatrix* bottomOf(const osg::CullStack::MatrixStack& stack)
{
    if (stack.empty())
        return nullptr;
    return stack._stack.empty() ? stack._value.get() : stack._stack.front().get();
}

class VisitorChildAcceptor : public ChildAcceptor
{
public:
    explicit VisitorChildAcceptor(std::function<void(osg::Node&, bool)> accept) : _accept(std::move(accept)) {}
    void accept(osg::Node& child, bool decided) override { _accept(child, decided); }

private:
    std::function<void(osg::Node&, bool)> _accept;
};
} // namespace

void CullVisitor::activate(osg::Node& root)
{
    _activeRoot = &root;
    _active = {};
    const osg::RefMatrix* modelView = bottomOf(getModelViewStack());
    const osg::RefMatrix* projection = bottomOf(getProjectionStack());
    if (!modelView || !projection)
        return;
    // note: the bottom of the stacks holds the camera's view and projection, the frame of the scene
    // roots, whichever nested transform or camera the first drawable sits under.
    _active = _shared->cullerFor(root).cull(*this, root, *modelView, *projection);
}

void CullVisitor::acceptChild(osg::Node& child, bool decided)
{
    const bool outer = _decided;
    _decided = outer || decided;
    child.accept(*this);
    _decided = outer;
}

bool CullVisitor::cullRootOverTree(osg::Group& root)
{
    const osg::NodePath& path = getNodePath();
    if (path.size() != 1 || !enterableNode(root))
        return false;
    if (path.front() != _activeRoot)
        activate(root);
    if (!_active.visible || _active.everything || !_active.scene->cullTree)
        return false;
    VisitorChildAcceptor acceptor([this](osg::Node& child, bool decided) { acceptChild(child, decided); });
    TreeCull(*this, *_active.scene, *_active.visible, acceptor).cullGroup(0, root);
    return true;
}

namespace
{
// OSG's own cull of `node`, unless osgVis has already decided it where it stands.
template <class Node> void osgCullsUnless(bool decided, osgUtil::CullVisitor& visitor, Node& node)
{
    if (!decided)
        visitor.osgUtil::CullVisitor::apply(node);
}
} // namespace

void CullVisitor::apply(osg::Group& node)
{
    osgCullsUnless(cullRootOverTree(node), *this, node);
}

void CullVisitor::apply(osg::Geode& node)
{
    osgCullsUnless(cullRootOverTree(node), *this, node);
}

void CullVisitor::apply(osg::Transform& node)
{
    osgCullsUnless(cullRootOverTree(node), *this, node);
}

void CullVisitor::apply(osg::Drawable& drawable)
{
    const osg::NodePath& path = getNodePath();
    if (!_decided && !path.empty())
    {
        if (path.front() != _activeRoot)
            activate(*path.front());
        if (_active.visible && !_active.everything)
        {
            const core::ObjectId id = _active.scene->find(&drawable, path);
            if (id != core::InvalidObject && _active.scene->refs[id].clusters)
            {
                if (!drawClusteredWhole(*this, drawable, *_active.scene->refs[id].clusters, id, *_active.visible))
                    return;
            }
            else if (id != core::InvalidObject && !_active.visible->test(id))
                return;
        }
    }
    osgUtil::CullVisitor::apply(drawable);
}

bool CullVisitor::pagedNodeHidden(osg::Group& node)
{
    const osg::NodePath& path = getNodePath();
    if (_decided || path.empty())
        return false;
    if (path.front() != _activeRoot)
        activate(*path.front());
    if (!_active.visible || _active.everything)
        return false;
    const core::ObjectId id = _active.scene->find(&node, path);
    return id != core::InvalidObject && !_active.visible->test(id);
}

void CullVisitor::apply(osg::PagedLOD& node)
{
    osgCullsUnless(pagedNodeHidden(node), *this, node);
}

void CullVisitor::apply(osg::ProxyNode& node)
{
    osgCullsUnless(pagedNodeHidden(node), *this, node);
}

void CullVisitor::installAsPrototype(const std::string& modes)
{
    osgUtil::CullVisitor::prototype() = new CullVisitor(modes);
}

namespace
{
// Replaces a SceneView's three cull visitors (mono, left, right eye) with clones of `prototype`,
// keeping the identifiers the Renderer gave them so per-view state stays keyed per eye.
void replaceCullVisitors(osgUtil::SceneView& sceneView, const CullVisitor& prototype)
{
    const auto replace = [&](osgUtil::CullVisitor* old, auto set) {
        osg::ref_ptr<osgUtil::CullVisitor> fresh = prototype.clone();
        if (old)
            fresh->setIdentifier(old->getIdentifier());
        (sceneView.*set)(fresh.get());
    };
    replace(sceneView.getCullVisitor(), &osgUtil::SceneView::setCullVisitor);
    replace(sceneView.getCullVisitorLeft(), &osgUtil::SceneView::setCullVisitorLeft);
    replace(sceneView.getCullVisitorRight(), &osgUtil::SceneView::setCullVisitorRight);
}

void installOnCamera(osg::Camera* camera, const CullVisitor& prototype)
{
    auto* renderer = camera ? dynamic_cast<osgViewer::Renderer*>(camera->getRenderer()) : nullptr;
    if (!renderer)
        return;
    for (unsigned i = 0; i < 2; ++i)
        if (osgUtil::SceneView* sceneView = renderer->getSceneView(i))
            replaceCullVisitors(*sceneView, prototype);
}
} // namespace

void CullVisitor::installOn(osgViewer::View& view, const std::string& modes)
{
    osg::ref_ptr<CullVisitor> prototype = new CullVisitor(modes);
    installOnCamera(view.getCamera(), *prototype);
    for (unsigned i = 0; i < view.getNumSlaves(); ++i)
        installOnCamera(view.getSlave(i)._camera.get(), *prototype);
}
} // namespace osgVis
