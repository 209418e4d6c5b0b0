// SPDX-License-Identifier: MIT
#include "IdViewer.h"

#include <osgVis/oracle/OffscreenContext.h>

#include <osgUtil/CullVisitor>
#include <osgViewer/Renderer>

#include <stdexcept>

namespace osgVis::oracle
{
IdViewer::IdViewer(unsigned width, unsigned height, osg::Node* scene) : _scene(scene)
{
    _image = new osg::Image;
    _image->allocateImage(int(width), int(height), 1, GL_RGBA, GL_UNSIGNED_BYTE);

    _viewer = new osgViewer::Viewer;
    _viewer->setThreadingModel(osgViewer::ViewerBase::SingleThreaded);
    // note: OSG otherwise pins the calling thread (and every thread it starts later) to core 0
    _viewer->setUseConfigureAffinity(false);
    _viewer->setReleaseContextAtEndOfFrameHint(true);
    _viewer->setLightingMode(osg::View::NO_LIGHT);

    osg::Camera* camera = _viewer->getCamera();
    // The image goes to an FBO; the pbuffer only carries the context.
    camera->setGraphicsContext(createOffscreenContext(16, 16).get());
    camera->setViewport(0, 0, int(width), int(height));
    camera->setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    camera->attach(osg::Camera::COLOR_BUFFER, _image.get());
    camera->attach(osg::Camera::DEPTH_BUFFER, GL_DEPTH_COMPONENT24);
    camera->setClearColor(osg::Vec4(0.0f, 0.0f, 0.0f, 0.0f));
    camera->setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    camera->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera->setCullingMode(camera->getCullingMode() & ~osg::CullSettings::SMALL_FEATURE_CULLING);
    camera->setCullMask(~0u);
    _viewer->setSceneData(_scene.get());

    // note: the application may have installed a visibility-culling CullVisitor as the prototype; the
    // judge must cull with OSG's own (frustum only)
    if (auto* renderer = dynamic_cast<osgViewer::Renderer*>(camera->getRenderer()))
        for (unsigned i = 0; i < 2; ++i)
            if (osgUtil::SceneView* sceneView = renderer->getSceneView(i))
                sceneView->setCullVisitor(new osgUtil::CullVisitor);

    _viewer->realize();
    if (!_viewer->isRealized())
        throw std::runtime_error("osgVis oracle: cannot realize the offscreen viewer");
}

IdViewer::~IdViewer()
{
    // The drawables are shared with the application's graph: drop the GL objects they hold for this
    // context, or a later context reusing its id would believe they exist.
    osg::GraphicsContext* context = _viewer->getCamera()->getGraphicsContext();
    if (context && context->valid() && context->makeCurrent())
    {
        _scene->releaseGLObjects(context->getState());
        context->releaseContext();
    }
    _viewer = nullptr;
}

void IdViewer::drawFrame(const osg::Matrixd& view, const osg::Matrixd& projection)
{
    osg::Camera* camera = _viewer->getCamera();
    camera->setViewMatrix(view);
    camera->setProjectionMatrix(projection);
    // No event or update traversal: the shared drawables' update callbacks belong to the application.
    _viewer->advance();
    _viewer->renderingTraversals();
}
} // namespace osgVis::oracle
