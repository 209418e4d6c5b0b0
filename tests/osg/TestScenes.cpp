// SPDX-License-Identifier: MIT
#include "TestScenes.h"

#include <osg/StateSet>
#include <osg/Viewport>
#include <osgUtil/RenderStage>
#include <osgUtil/StateGraph>

#include <algorithm>

namespace osgVis::test
{
osg::ref_ptr<osg::Geometry> makeBox(const osg::Vec3& min, const osg::Vec3& max, const osg::Vec4& colour)
{
    osg::ref_ptr<osg::Geometry> box = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
    for (int i = 0; i < 8; ++i) // corner i: bit 0 → x max, bit 1 → y max, bit 2 → z max
        vertices->push_back(
            osg::Vec3((i & 1) ? max.x() : min.x(), (i & 2) ? max.y() : min.y(), (i & 4) ? max.z() : min.z()));
    box->setVertexArray(vertices);
    osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array;
    colours->push_back(colour);
    box->setColorArray(colours, osg::Array::BIND_OVERALL);
    static const unsigned short faces[] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                                           2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
    box->addPrimitiveSet(new osg::DrawElementsUShort(GL_TRIANGLES, 36, faces));
    box->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    return box;
}

namespace
{
void collectDrawn(const osgUtil::StateGraph& graph, std::set<const osg::Drawable*>& drawn)
{
    for (const auto& leaf : graph._leaves)
        drawn.insert(leaf->getDrawable());
    for (const auto& child : graph._children)
        collectDrawn(*child.second, drawn);
}
} // namespace

TestView::TestView(osgUtil::CullVisitor* cv) : _cv(cv ? cv : new osgUtil::CullVisitor), _frameStamp(new osg::FrameStamp)
{
    _cv->setIdentifier(new osgUtil::CullVisitor::Identifier);
    _cv->setCullingMode(osg::CullSettings::NO_CULLING);
    _cv->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
}

osg::Matrixd TestView::lookingDownX()
{
    return osg::Matrixd::lookAt(osg::Vec3d(0, 0, 0), osg::Vec3d(1, 0, 0), osg::Vec3d(0, 0, 1));
}

std::set<const osg::Drawable*> TestView::draw(osg::Node& root, const osg::Matrixd& view)
{
    osg::ref_ptr<osgUtil::StateGraph> stateGraph = new osgUtil::StateGraph;
    osg::ref_ptr<osgUtil::RenderStage> stage = new osgUtil::RenderStage;
    osg::ref_ptr<osg::Viewport> viewport = new osg::Viewport(0, 0, 256, 256);
    stage->setViewport(viewport);
    _frameStamp->setFrameNumber(_frames);
    _frameStamp->setReferenceTime(_frames / 60.0);
    _frameStamp->setSimulationTime(_frames / 60.0);
    ++_frames;
    _cv->reset();
    _cv->setFrameStamp(_frameStamp);
    _cv->setStateGraph(stateGraph);
    _cv->setRenderStage(stage);
    _cv->pushViewport(viewport);
    _cv->pushProjectionMatrix(new osg::RefMatrix(osg::Matrixd::perspective(40.0, 1.0, 0.5, 1000.0)));
    _cv->pushModelViewMatrix(new osg::RefMatrix(view), osg::Transform::ABSOLUTE_RF);
    root.accept(*_cv);
    _cv->popModelViewMatrix();
    _cv->popProjectionMatrix();
    _cv->popViewport();
    std::set<const osg::Drawable*> drawn;
    collectDrawn(*stateGraph, drawn);
    return drawn;
}

osg::ref_ptr<osg::GraphicsContext> createTestContext(unsigned width, unsigned height)
{
    osg::ref_ptr<osg::GraphicsContext::Traits> traits = new osg::GraphicsContext::Traits;
    traits->readDISPLAY();
    traits->width = int(width);
    traits->height = int(height);
    traits->red = traits->green = traits->blue = traits->alpha = 8;
    traits->depth = 24;
    traits->windowDecoration = false;
    traits->doubleBuffer = true;
    traits->pbuffer = true;
    osg::ref_ptr<osg::GraphicsContext> gc = osg::GraphicsContext::createGraphicsContext(traits);
    if (!gc)
    {
        traits->pbuffer = false; // some GLX servers lack pbuffers: a small window does as well
        gc = osg::GraphicsContext::createGraphicsContext(traits);
    }
    return gc;
}

osg::ref_ptr<CaptureImage> setUpCapturingCamera(osg::Camera& camera, unsigned width, unsigned height)
{
    osg::ref_ptr<osg::GraphicsContext> gc = createTestContext(width, height);
    if (!gc)
        return nullptr;
    camera.setGraphicsContext(gc);
    camera.setViewport(0, 0, int(width), int(height));
    const GLenum buffer = gc->getTraits()->doubleBuffer ? GL_BACK : GL_FRONT;
    camera.setDrawBuffer(buffer);
    camera.setReadBuffer(buffer);
    camera.setClearColor(osg::Vec4(0, 0, 0, 1));
    camera.setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
    camera.setCullingMode(camera.getCullingMode() & ~osg::CullSettings::SMALL_FEATURE_CULLING);
    osg::ref_ptr<CaptureImage> capture = new CaptureImage(width, height);
    camera.setFinalDrawCallback(capture);
    return capture;
}

void CaptureImage::operator()(osg::RenderInfo&) const
{
    image->readPixels(0, 0, int(width), int(height), GL_RGBA, GL_UNSIGNED_BYTE);
    std::lock_guard<std::mutex> lock(_mutex);
    if (keepFrames)
        _frames.push_back(new osg::Image(*image, osg::CopyOp::DEEP_COPY_ALL));
    ++_draws;
    _drawn.notify_all();
}

std::vector<osg::ref_ptr<osg::Image>> CaptureImage::waitForFrames(unsigned draws, std::chrono::seconds timeout) const
{
    std::unique_lock<std::mutex> lock(_mutex);
    _drawn.wait_for(lock, timeout, [&] { return _draws >= draws; });
    return _frames;
}

bool samePixels(const osg::Image& a, const osg::Image& b)
{
    return a.s() == b.s() && a.t() == b.t() && a.getTotalSizeInBytes() == b.getTotalSizeInBytes() &&
           std::equal(a.data(), a.data() + a.getTotalSizeInBytes(), b.data());
}

unsigned litPixels(const osg::Image& image)
{
    unsigned lit = 0;
    for (int y = 0; y < image.t(); ++y)
        for (int x = 0; x < image.s(); ++x)
        {
            const unsigned char* p = image.data(x, y);
            lit += (p[0] | p[1] | p[2]) != 0;
        }
    return lit;
}
} // namespace osgVis::test
