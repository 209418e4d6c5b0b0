// SPDX-License-Identifier: MIT
#include "IdRenderer.h"

#include "IdColour.h"

#include <osgVis/oracle/OffscreenContext.h>

#include <osgUtil/CullVisitor>
#include <osgViewer/Renderer>

#include <cstring>
#include <limits>
#include <stdexcept>

namespace osgVis::oracle
{
namespace
{
constexpr std::uint32_t NoChild = std::numeric_limits<std::uint32_t>::max();
} // namespace

IdRenderer::IdRenderer(unsigned width, unsigned height, const IdPassState& pass,
                       const std::vector<std::pair<std::uint32_t, osg::ref_ptr<osg::Node>>>& opaque,
                       const std::vector<std::pair<std::uint32_t, osg::ref_ptr<osg::Node>>>& transparent,
                       std::size_t objectCount)
    : _transparentChildOf(objectCount, NoChild)
{
    _root = new osg::Group;
    _root->setStateSet(pass.root.get());
    _opaqueIds = new osg::Group;
    _opaqueIds->setStateSet(pass.opaqueIds.get());
    _opaqueDepth = new osg::Group;
    _opaqueDepth->setStateSet(pass.opaqueDepth.get());
    _transparentIds = new osg::Switch;
    _transparentIds->setStateSet(pass.transparentIds.get());
    for (const auto& [index, chain] : opaque)
    {
        _opaqueIds->addChild(chain.get());
        _opaqueDepth->addChild(chain.get());
    }
    for (const auto& [index, chain] : transparent)
    {
        _transparentChildOf[index] = _transparentIds->getNumChildren();
        _transparentIds->addChild(chain.get());
    }
    _root->addChild(_opaqueIds.get());
    _root->addChild(_opaqueDepth.get());
    _root->addChild(_transparentIds.get());

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
    _viewer->setSceneData(_root.get());

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

IdRenderer::~IdRenderer()
{
    // The drawables are shared with the application's graph: drop the GL objects they hold for this
    // context, or a later context reusing its id would believe they exist.
    osg::GraphicsContext* context = _viewer->getCamera()->getGraphicsContext();
    if (context && context->valid() && context->makeCurrent())
    {
        _root->releaseGLObjects(context->getState());
        context->releaseContext();
    }
    _viewer = nullptr;
}

void IdRenderer::drawFrame()
{
    // No event or update traversal: the shared drawables' update callbacks belong to the application.
    _viewer->advance();
    _viewer->renderingTraversals();
}

std::size_t IdRenderer::collectIds(std::vector<std::uint8_t>& seen, std::vector<std::uint32_t>* pixelCounts)
{
    const std::size_t pixels = std::size_t(_image->s()) * std::size_t(_image->t());
    const unsigned char* data = _image->data();
    std::size_t found = 0;
    std::uint32_t previous = 0;
    for (std::size_t p = 0; p < pixels; ++p)
    {
        std::uint32_t rgba;
        std::memcpy(&rgba, data + 4 * p, 4);
        const std::uint32_t idPlusOne = idPlusOneOfPixel(rgba);
        if (pixelCounts && idPlusOne != 0 && idPlusOne <= pixelCounts->size())
            ++(*pixelCounts)[idPlusOne - 1];
        if (idPlusOne == previous)
            continue; // runs of one id are the common case
        previous = idPlusOne;
        if (idPlusOne == 0 || idPlusOne > seen.size() || seen[idPlusOne - 1])
            continue;
        const std::uint32_t index = idPlusOne - 1;
        seen[index] = 1;
        ++found;
        if (_transparentChildOf[index] != NoChild)
            _transparentIds->setValue(_transparentChildOf[index], false);
    }
    return found;
}

void IdRenderer::render(const osg::Matrixd& view, const osg::Matrixd& projection, std::vector<std::uint8_t>& seen,
                        std::vector<std::uint32_t>* pixels)
{
    osg::Camera* camera = _viewer->getCamera();
    camera->setViewMatrix(view);
    camera->setProjectionMatrix(projection);

    _opaqueIds->setNodeMask(~0u);
    _opaqueDepth->setNodeMask(0u);
    _transparentIds->setNodeMask(0u);
    drawFrame();
    collectIds(seen, pixels);
    if (_transparentIds->getNumChildren() == 0)
        return;

    // Transparent objects hide nothing, so each pass shows only the last one drawn at a pixel: repeat
    // without the ones found until a pass finds none.
    _opaqueIds->setNodeMask(0u);
    _opaqueDepth->setNodeMask(~0u);
    _transparentIds->setNodeMask(~0u);
    _transparentIds->setAllChildrenOn();
    do
        drawFrame();
    while (collectIds(seen, pixels) != 0);
}
} // namespace osgVis::oracle
