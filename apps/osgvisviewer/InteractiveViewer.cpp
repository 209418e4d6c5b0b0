// SPDX-License-Identifier: MIT
#include "InteractiveViewer.h"

#include "BuildingTool.h"
#include <CameraSetup.h>
#include "CullingModes.h"
#include <ThreadingModel.h>
#include "DebugMap.h"
#include "WalkManipulator.h"

#include <OccluderReport.h>

#include <osgVis/Statistics>

#include <osgGA/StateSetManipulator>
#include <osgText/Text>
#include <osgViewer/Viewer>
#include <osgViewer/ViewerEventHandlers>

#include <cstdlib>
#include <iostream>
#include <mutex>

namespace osgVis::viewer
{
namespace
{
// The keys that matter, named in the window itself (a newcomer should not need --help to find the
// map and the statistics), with the current mode.
std::string keyHints(const std::string& mode)
{
    return "mode " + mode + " | m: mode  t: map  i: stats  y: why  p: play  h: help";
}

// Keeps the hints line current: the mode the m key chose, and whether do no harm has backed off
// (more consecutive frames skipped the chain than one probe block holds).
class KeyHintsUpdate : public osg::Drawable::UpdateCallback
{
public:
    KeyHintsUpdate(CullingModes& modes, const std::string& mode) : _modes(modes), _mode(mode) {}
    void setMode(const std::string& mode)
    {
        std::lock_guard<std::mutex> lock(_mutex);
        _mode = mode;
        _shown.clear();
    }
    void update(osg::NodeVisitor*, osg::Drawable* drawable) override
    {
        const VisibilityGroup* group = _modes.visibilityGroup();
        const CullStatistics figures = group ? group->getLastStatistics() : CullStatistics{};
        _skippedInARow = figures.backedOff ? _skippedInARow + 1 : 0;
        std::lock_guard<std::mutex> lock(_mutex);
        const std::string text =
            (_skippedInARow > 8 ? "backed off: culling costs more than it saves here, OSG culls alone\n" : "") +
            keyHints(_mode);
        if (text != _shown)
            static_cast<osgText::Text*>(drawable)->setText(_shown = text);
    }

private:
    CullingModes& _modes;
    std::mutex _mutex;
    std::string _mode, _shown;
    unsigned _skippedInARow = 0;
};

osg::ref_ptr<osg::Camera> createKeyHintsOverlay(unsigned width, unsigned height, osg::ref_ptr<osgText::Text>& text)
{
    osg::ref_ptr<osg::Camera> hud = new osg::Camera;
    hud->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
    hud->setProjectionMatrixAsOrtho2D(0, width, 0, height);
    hud->setViewMatrix(osg::Matrix::identity());
    hud->setClearMask(GL_DEPTH_BUFFER_BIT);
    hud->setRenderOrder(osg::Camera::POST_RENDER);
    hud->setAllowEventFocus(false);
    text = new osgText::Text;
    text->setDataVariance(osg::Object::DYNAMIC); // changed by the m key while a draw thread may draw it
    text->setCharacterSize(14.0f);
    text->setPosition(osg::Vec3(10.0f, 10.0f, 0.0f));
    text->setAlignment(osgText::Text::LEFT_BOTTOM_BASE_LINE); // a status line above grows upwards
    text->setColor(osg::Vec4(1.0f, 1.0f, 0.6f, 1.0f));
    text->setBackdropType(osgText::Text::OUTLINE);
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(text.get());
    geode->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    hud->addChild(geode.get());
    return hud;
}

// Keys of the viewer itself: `m` cycles the culling mode, `t` shows or hides the debug map, `b`
// drops a building ahead, `B` or Delete deletes the building nearest the centre of the view.
class ViewerKeys : public osgGA::GUIEventHandler
{
public:
    ViewerKeys(CullingModes& modes, DebugMap& map, BuildingTool& buildings, const osg::Camera& camera,
               KeyHintsUpdate* hints, osg::Node& model)
        : _modes(modes), _map(map), _buildings(buildings), _camera(camera), _hints(hints), _model(model)
    {
    }

    bool handle(const osgGA::GUIEventAdapter& ea, osgGA::GUIActionAdapter&) override
    {
        if (ea.getHandled() || ea.getEventType() != osgGA::GUIEventAdapter::KEYDOWN)
            return false;
        if (ea.getKey() == 'm')
        {
            const std::string next = _modes.nextMode();
            _modes.requestMode(next);
            _hints->setMode(next);
            std::cout << "osgvisviewer: mode " << next << std::endl;
            return true;
        }
        if (ea.getKey() == 'y')
        {
            // note: extracted afresh with triangles, so edits made with b/B are included
            std::cout << "osgvisviewer: explain (why culling does or does not work on this model):\n";
            apps::writeOccluderReport(std::cout, apps::reportOccluders(*extractScene(_model)));
            std::cout << "  (osgvisbench --explain also lists the objects a mode never culls although hidden)"
                      << std::endl;
            return true;
        }
        if (ea.getKey() == 't')
        {
            _map.setEnabled(!_map.enabled());
            return true;
        }
        if (ea.getKey() == 'b')
        {
            if (_buildings.dropAhead(_camera.getViewMatrix()))
                std::cout << "osgvisviewer: dropped a building" << std::endl;
            return true;
        }
        if (ea.getKey() == 'B' || ea.getKey() == osgGA::GUIEventAdapter::KEY_Delete)
        {
            const std::string removed = _buildings.removeNearestCentre(_camera.getViewMatrix());
            std::cout << "osgvisviewer: " << (removed.empty() ? "no building ahead to delete" : "deleted " + removed)
                      << std::endl;
            return true;
        }
        return false;
    }

    void getUsage(osg::ApplicationUsage& usage) const override
    {
        usage.addKeyboardMouseBinding("m", "Next culling mode (osg, then every registered module)");
        usage.addKeyboardMouseBinding("y", "Why (not): which objects may occlude, and why the others may not");
        usage.addKeyboardMouseBinding("t", "Show / hide the top-down map: drawn green, culled red, outside grey");
        usage.addKeyboardMouseBinding("b", "Drop a building box a few metres ahead");
        usage.addKeyboardMouseBinding("B", "Delete the building nearest the centre of the view (also Delete)");
    }

private:
    CullingModes& _modes;
    DebugMap& _map;
    BuildingTool& _buildings;
    const osg::Camera& _camera;
    osg::ref_ptr<KeyHintsUpdate> _hints;
    osg::Node& _model;
};

// Walking speed: crossing the scene takes about twenty seconds.
double defaultSpeed(const core::Aabb& bounds)
{
    return bounds.empty() ? 1.0 : std::max(1e-3, glm::length(bounds.extent()) / 20.0);
}
} // namespace

int runInteractive(const apps::LoadedScene& scene, const ViewerOptions& options)
{
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display)
    {
        std::cerr << "osgvisviewer: no X display (DISPLAY is not set). Run it on a desktop, or render the walk to "
                     "images with --headless OUTDIR under xvfb-run -a.\n";
        return 3;
    }

    CullingModes modes(scene.model.get(), options.mode, options.async);
    DebugMap map(*scene.objects, modes);
    osg::ref_ptr<osg::Group> root = map.sceneWithMap(modes);

    osgViewer::Viewer viewer;
    if (!options.threading.empty())
        viewer.setThreadingModel(apps::parseThreadingModel(options.threading));
    osg::ref_ptr<osgText::Text> hints;
    root->addChild(createKeyHintsOverlay(scene.walk.width, scene.walk.height, hints));
    osg::ref_ptr<KeyHintsUpdate> hintsUpdate = new KeyHintsUpdate(modes, options.mode);
    hints->setUpdateCallback(hintsUpdate.get());
    viewer.setSceneData(root.get());
    viewer.setUpViewInWindow(50, 50, int(scene.walk.width), int(scene.walk.height));
    osg::Camera* camera = viewer.getCamera();
    apps::applyWalkProjection(*camera, scene.walk.projection, scene.walk.aspect());
    map.setObservedCamera(camera);

    viewer.setCameraManipulator(
        new WalkManipulator(scene.walk, defaultSpeed(scene.objects->scene.bounds()), options.recordPath));
    // Edits go to the model itself, so they survive mode changes; the current VisibilityGroup (none
    // in osg mode) re-extracts with stable ids at its next cull.
    BuildingTool buildings(*scene.model,
                           [&modes]
                           {
                               if (VisibilityGroup* group = modes.visibilityGroup())
                                   group->dirtyScene();
                           });
    viewer.addEventHandler(new ViewerKeys(modes, map, buildings, *camera, hintsUpdate.get(), *scene.model));

    // OSG's usual handlers, with keys moved off w/s/e (walking) and m/t (mode, map).
    osg::ref_ptr<osgViewer::StatsHandler> stats = new osgViewer::StatsHandler;
    stats->setKeyEventTogglesOnScreenStats('i');
    stats->setKeyEventPrintsOutStats('I');
    addStatsLines(*stats);
    viewer.addEventHandler(stats.get());
    viewer.addEventHandler(new osgViewer::WindowSizeHandler);
    osg::ref_ptr<osgViewer::ThreadingHandler> threading = new osgViewer::ThreadingHandler;
    threading->setKeyEventChangeThreadingModel('n');
    threading->setKeyEventChangeEndBarrierPosition('N');
    viewer.addEventHandler(threading.get());
    osg::ref_ptr<osgGA::StateSetManipulator> state = new osgGA::StateSetManipulator(camera->getOrCreateStateSet());
    state->setKeyEventCyclePolygonMode('o');
    state->setKeyEventToggleTexturing('x');
    state->setKeyEventToggleBackfaceCulling('k'); // b drops a building
    viewer.addEventHandler(state.get());
    viewer.addEventHandler(new osgViewer::ScreenCaptureHandler);
    osg::ref_ptr<osgViewer::HelpHandler> help = new osgViewer::HelpHandler(new osg::ApplicationUsage);
    viewer.addEventHandler(help.get());

    std::cout << "osgvisviewer: " << scene.name << ", walk " << scene.walkSource << ", mode " << options.mode
              << " (h: help, m: next mode, t: map, y: why (not) culled, p: play walk, b/B: drop/delete a building)" << std::endl;
    return viewer.run();
}
} // namespace osgVis::viewer
