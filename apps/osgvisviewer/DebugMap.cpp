// SPDX-License-Identifier: MIT
#include "DebugMap.h"

#include <CameraSetup.h>
#include "CullingModes.h"
#include "MapGeometry.h"

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/scene/View.h>

#include <osg/BlendFunc>
#include <osg/Geode>
#include <osg/LineWidth>
#include <osg/Point>

#include <algorithm>
#include <iostream>
#include <sstream>

namespace osgVis::viewer
{
namespace
{
const osg::Vec4 DrawnColour(0.25f, 0.85f, 0.3f, 1.0f);
const osg::Vec4 CulledColour(0.95f, 0.2f, 0.2f, 1.0f);
const osg::Vec4 OutsideColour(0.55f, 0.55f, 0.55f, 1.0f);
const float FillAlpha = 0.35f;
} // namespace

class DebugMap::Refresh : public osg::NodeCallback
{
public:
    explicit Refresh(DebugMap& owner) : _owner(owner) {}

    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        const osg::FrameStamp* stamp = nv->getFrameStamp();
        _owner.refresh(stamp ? stamp->getSimulationTime() : 0.0);
        traverse(node, nv);
    }

private:
    DebugMap& _owner;
};

DebugMap::DebugMap(const ExtractedScene& objects, const CullingModes& modes) : _objects(&objects), _modes(modes)
{
    _camera = new osg::Camera;
    _camera->setName("osgvisviewer debug map");
    _camera->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
    _camera->setRenderOrder(osg::Camera::POST_RENDER);
    _camera->setClearMask(GL_DEPTH_BUFFER_BIT);
    _camera->setAllowEventFocus(false);
    _camera->setViewMatrix(osg::Matrixd::identity());
    _camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    osg::StateSet* state = _camera->getOrCreateStateSet();
    state->setMode(GL_LIGHTING, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    state->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    state->setMode(GL_CULL_FACE, osg::StateAttribute::OFF | osg::StateAttribute::PROTECTED);
    state->setMode(GL_BLEND, osg::StateAttribute::ON);
    state->setAttributeAndModes(new osg::BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA));
    state->setAttribute(new osg::LineWidth(1.0f));
    _camera->setUpdateCallback(new Refresh(*this));

    buildGeometry();
    setViewport(8, 8, 320, 320);
    setEnabled(false);
}

void DebugMap::buildGeometry()
{
    const std::vector<core::SceneObject>& objects = _objects->scene.objects;
    _drawOrder.clear();
    for (const core::SceneObject& object : objects)
        if (!(object.flags & core::OBJECT_ALWAYS_VISIBLE) && !object.bounds.empty())
            _drawOrder.push_back(object.id);
    auto footprint = [&](core::ObjectId id)
    {
        const core::Vec3 e = objects[id].bounds.extent();
        return e.x * e.y;
    };
    std::stable_sort(_drawOrder.begin(), _drawOrder.end(),
                     [&](core::ObjectId a, core::ObjectId b) { return footprint(a) > footprint(b); });

    const unsigned count = unsigned(_drawOrder.size());
    osg::ref_ptr<osg::Geometry> background =
        makeMapLayer(GL_QUADS, 4, BackgroundBin, osg::Vec4(0.08f, 0.08f, 0.1f, 1.0f), false);
    background->setName("background");
    _fills = makeMapLayer(GL_QUADS, 4 * count, ObjectFillBin, OutsideColour, true);
    _outlines = makeMapLayer(GL_LINES, 8 * count, ObjectOutlineBin, OutsideColour, true);
    _frustum = makeMapLayer(GL_LINES, 24, FrustumBin, osg::Vec4(1.0f, 0.9f, 0.2f, 1.0f), false);
    _eye = makeMapLayer(GL_POINTS, 1, EyeBin, osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f), false);
    _eye->getOrCreateStateSet()->setAttribute(new osg::Point(7.0f));

    osg::Vec3Array& fill = static_cast<osg::Vec3Array&>(*_fills->getVertexArray());
    osg::Vec3Array& outline = static_cast<osg::Vec3Array&>(*_outlines->getVertexArray());
    for (unsigned i = 0; i < count; ++i)
    {
        setFootprint(fill, outline, i, objects[_drawOrder[i]].bounds);
    }

    _label = new osgText::Text;
    _label->setDataVariance(osg::Object::DYNAMIC);
    _label->setCharacterSizeMode(osgText::Text::SCREEN_COORDS);
    _label->setCharacterSize(13.0f);
    _label->setAlignment(osgText::Text::LEFT_TOP);
    _label->setColor(osg::Vec4(1.0f, 1.0f, 1.0f, 1.0f));
    _label->getOrCreateStateSet()->setRenderBinDetails(LabelBin, "RenderBin");

    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    for (osg::Drawable* drawable :
         {static_cast<osg::Drawable*>(background.get()), static_cast<osg::Drawable*>(_fills.get()),
          static_cast<osg::Drawable*>(_outlines.get()), static_cast<osg::Drawable*>(_frustum.get()),
          static_cast<osg::Drawable*>(_eye.get()), static_cast<osg::Drawable*>(_label.get())})
        geode->addDrawable(drawable);
    for (osg::Drawable* drawable : _recordLayers.drawables())
        geode->addDrawable(drawable);
    // note: the map's own geometry must never be culled away by small-feature or frustum tests.
    geode->setCullingActive(false);
    _camera->addChild(geode.get());
}

osg::ref_ptr<osg::Group> DebugMap::sceneWithMap(const CullingModes& modes) const
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    root->addChild(modes.node());
    root->addChild(_camera.get());
    return root;
}

void DebugMap::followMode()
{
    VisibilityGroup* group = _modes.visibilityGroup();
    osg::ref_ptr<const ExtractedScene> groupScene =
        (group && _modes.mode() != OsgMode) ? group->getViewCuller()->getScene() : nullptr;
    // note: the group extracts its own child, the model, in the same depth-first order as _objects;
    // a count mismatch means the extractions disagree and only the frustum test is trustworthy.
    if (groupScene && groupScene->scene.objects.size() != _objects->scene.objects.size())
        groupScene = nullptr;
    if (_modes.mode() == _mode && groupScene == _chainScene)
        return;
    _mode = _modes.mode();
    _chainScene = groupScene;
    _chain = core::ModuleChain();
    if (!_chainScene)
        return;
    try
    {
        _chain = core::createChain(_mode);
        _chain.setScene(_chainScene->scene);
        // Modules with a spatial structure describe each query here; the others leave it empty.
        for (std::size_t stage = 0; stage < _chain.size(); ++stage)
            _chain.module(stage).setDebugRecord(&_record);
    }
    catch (const std::exception& e)
    {
        std::cerr << "osgvisviewer: the map shows the frustum test only: mode '" << _mode << "' failed: " << e.what()
                  << "\n";
        _chain = core::ModuleChain();
    }
}

void DebugMap::setEnabled(bool enabled)
{
    _camera->setNodeMask(enabled ? ~0u : 0u);
}

void DebugMap::setViewport(int x, int y, int width, int height)
{
    _camera->setViewport(x, y, width, height);
    fitProjection();
}

void DebugMap::fitProjection()
{
    core::Aabb bounds;
    for (core::ObjectId id : _drawOrder)
        bounds.expand(_objects->scene.objects[id].bounds);
    if (bounds.empty())
        bounds = core::Aabb(core::Vec3(-1.0), core::Vec3(1.0));
    const osg::Viewport* viewport = _camera->getViewport();
    const double aspect = viewport->width() / std::max(1.0, viewport->height());
    const core::Vec3 center = bounds.center();
    double halfX = 0.55 * std::max(bounds.extent().x, 1e-6);
    double halfY = 0.55 * std::max(bounds.extent().y, 1e-6);
    if (halfX / halfY < aspect)
        halfX = halfY * aspect;
    else
        halfY = halfX / aspect;
    _camera->setProjectionMatrixAsOrtho(center.x - halfX, center.x + halfX, center.y - halfY, center.y + halfY, -1.0,
                                        1.0);

    osg::Geometry* background = _camera->getChild(0)->asGeode()->getDrawable(0)->asGeometry();
    osg::Vec3Array& corners = static_cast<osg::Vec3Array&>(*background->getVertexArray());
    setPlanarVertex(corners, 0, center.x - halfX, center.y - halfY);
    setPlanarVertex(corners, 1, center.x + halfX, center.y - halfY);
    setPlanarVertex(corners, 2, center.x + halfX, center.y + halfY);
    setPlanarVertex(corners, 3, center.x - halfX, center.y + halfY);
    corners.dirty();
    background->dirtyBound();
    _label->setPosition(osg::Vec3(float(center.x - 0.97 * halfX), float(center.y + 0.97 * halfY), 0.0f));
}

void DebugMap::refresh(double time)
{
    osg::ref_ptr<osg::Camera> observed;
    if (!_observed.lock(observed) || !observed->getViewport())
        return;
    const osg::Viewport& viewport = *observed->getViewport();
    followMode();
    const core::View view =
        core::makeView(apps::toCoreMatrix(observed->getViewMatrix()), apps::toCoreMatrix(observed->getProjectionMatrix()), time,
                       std::uint32_t(viewport.width()), std::uint32_t(viewport.height()));
    classify(view);

    // The frustum's eight corners, from clip space back to the world, then flattened onto z = 0.
    const core::Mat4 clipToWorld = glm::inverse(view.projectionMatrix * view.viewMatrix);
    core::Vec3 corners[8];
    for (int i = 0; i < 8; ++i)
    {
        const core::Vec4 p =
            clipToWorld * core::Vec4((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0, 1.0);
        corners[i] = core::Vec3(p) / p.w;
    }
    static const int edges[12][2] = {{0, 1}, {1, 3}, {3, 2}, {2, 0}, {4, 5}, {5, 7},
                                     {7, 6}, {6, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    osg::Vec3Array& wedge = static_cast<osg::Vec3Array&>(*_frustum->getVertexArray());
    for (int e = 0; e < 12; ++e)
        for (int end = 0; end < 2; ++end)
            setPlanarVertex(wedge, 2 * e + end, corners[edges[e][end]].x, corners[edges[e][end]].y);
    wedge.dirty();
    _frustum->dirtyBound();

    osg::Vec3Array& eye = static_cast<osg::Vec3Array&>(*_eye->getVertexArray());
    setPlanarVertex(eye, 0, view.eye.x, view.eye.y);
    eye.dirty();
    _eye->dirtyBound();
}

void DebugMap::classify(const core::View& view)
{
    const std::vector<core::SceneObject>& objects = _objects->scene.objects;
    if (_chain.empty())
    {
        _visible.reset(objects.size());
        for (const core::SceneObject& object : objects)
            if (view.frustum.classify(object.bounds) != core::Containment::Outside)
                _visible.set(object.id);
    }
    else
    {
        _record.clear();
        _chain.cull(view, _visible);
    }
    if (_chain.empty())
        _record.clear();
    _recordLayers.update(_record);

    osg::Vec4Array& fill = static_cast<osg::Vec4Array&>(*_fills->getColorArray());
    osg::Vec4Array& outline = static_cast<osg::Vec4Array&>(*_outlines->getColorArray());
    std::size_t drawn = 0, culled = 0, outside = 0;
    for (std::size_t i = 0; i < _drawOrder.size(); ++i)
    {
        const core::SceneObject& object = objects[_drawOrder[i]];
        osg::Vec4 colour = CulledColour;
        if (_visible.test(object.id))
        {
            colour = DrawnColour;
            ++drawn;
        }
        else if (view.frustum.classify(object.bounds) == core::Containment::Outside)
        {
            colour = OutsideColour;
            ++outside;
        }
        else
        {
            ++culled;
        }
        std::fill(outline.begin() + 8 * i, outline.begin() + 8 * (i + 1), colour);
        colour.a() = FillAlpha;
        std::fill(fill.begin() + 4 * i, fill.begin() + 4 * (i + 1), colour);
    }
    fill.dirty();
    outline.dirty();

    std::ostringstream text;
    text << "mode " << _mode << (_chain.empty() && _mode != OsgMode ? " (frustum test)" : "") << "   t " << view.time
         << " s\n"
         << "drawn " << drawn << "  culled " << culled << "\n"
         << "outside " << outside << "  of " << objects.size();
    if (!_recordLayers.legend().empty())
        text << "\n" << _recordLayers.legend();
    _label->setText(text.str());
}
} // namespace osgVis::viewer
