// SPDX-License-Identifier: MIT
#include "SameImagePatterns.h"

#include "TestScenes.h"

#include <osg/AlphaFunc>
#include <osg/AnimationPath>
#include <osg/AutoTransform>
#include <osg/Billboard>
#include <osg/BlendFunc>
#include <osg/Camera>
#include <osg/ClipNode>
#include <osg/ClipPlane>
#include <osg/ClusterCullingCallback>
#include <osg/ColorMask>
#include <osg/ConvexPlanarOccluder>
#include <osg/CullFace>
#include <osg/Depth>
#include <osg/GL>
#include <osg/Geode>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/OccluderNode>
#include <osg/PolygonMode>
#include <osg/PolygonOffset>
#include <osg/PositionAttitudeTransform>
#include <osg/Program>
#include <osg/Projection>
#include <osg/Scissor>
#include <osg/Sequence>
#include <osg/Shader>
#include <osg/Stencil>
#include <osg/Switch>
#include <osg/Texture2D>
#include <osg/Transform>
#include <osg/Uniform>
#include <osgUtil/CullVisitor>
#include <osgUtil/SceneView>
#include <osgViewer/Renderer>

#include <cmath>

namespace osgVis::test::sameimage
{
namespace
{
using osg::Vec3;
using osg::Vec4;

constexpr double Pi = 3.14159265358979323846;
constexpr double Aspect = double(Width) / Height;
const Vec4 WallColour(0.6f, 0.6f, 0.6f, 1.f);
// A box's centre 120 m away, up and to the left, above the wall's top edge and in view from the eye's
// path.
const Vec3 FarBoxInView(-32, 120, 42);

// Distinct flat colours, none black and none the wall's grey.
Vec4 colourOf(unsigned i)
{
    static const Vec4 palette[] = {
        {1.0f, 0.2f, 0.2f, 1.f},  {0.2f, 1.0f, 0.2f, 1.f},  {0.2f, 0.2f, 1.0f, 1.f},  {1.0f, 1.0f, 0.2f, 1.f},
        {1.0f, 0.2f, 1.0f, 1.f},  {0.2f, 1.0f, 1.0f, 1.f},  {1.0f, 0.6f, 0.2f, 1.f},  {0.6f, 0.2f, 1.0f, 1.f},
        {0.2f, 0.6f, 0.2f, 1.f},  {0.6f, 0.2f, 0.2f, 1.f},  {0.2f, 0.2f, 0.6f, 1.f},  {1.0f, 0.8f, 0.8f, 1.f},
        {0.8f, 1.0f, 0.6f, 1.f},  {0.6f, 0.8f, 1.0f, 1.f},  {0.9f, 0.5f, 0.7f, 1.f},  {0.5f, 0.9f, 0.7f, 1.f},
        {0.7f, 0.5f, 0.3f, 1.f},  {0.3f, 0.5f, 0.7f, 1.f},  {0.9f, 0.9f, 0.5f, 1.f},  {0.4f, 0.7f, 0.4f, 1.f},
    };
    return palette[i % (sizeof(palette) / sizeof(palette[0]))];
}

osg::ref_ptr<osg::Geode> geodeOf(osg::Drawable* drawable)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(drawable);
    return geode;
}

// A box of half size `half` around `centre`, in its own geode.
osg::ref_ptr<osg::Geode> boxAt(const Vec3& centre, float half, const Vec4& colour)
{
    return geodeOf(makeBox(centre - Vec3(half, half, half), centre + Vec3(half, half, half), colour));
}

// One quad (two triangles, corners counter-clockwise as seen from its front), flat colour, lighting
// off; texture coordinates (0,0) (s,0) (s,t) (0,t) when `s` > 0.
osg::ref_ptr<osg::Geometry> makeQuad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec4& colour,
                                     float s = 0.f, float t = 1.f)
{
    osg::ref_ptr<osg::Geometry> quad = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> vertices = new osg::Vec3Array;
    vertices->push_back(a);
    vertices->push_back(b);
    vertices->push_back(c);
    vertices->push_back(d);
    quad->setVertexArray(vertices);
    osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array;
    colours->push_back(colour);
    quad->setColorArray(colours, osg::Array::BIND_OVERALL);
    if (s > 0.f)
    {
        osg::ref_ptr<osg::Vec2Array> texCoords = new osg::Vec2Array;
        texCoords->push_back(osg::Vec2(0, 0));
        texCoords->push_back(osg::Vec2(s, 0));
        texCoords->push_back(osg::Vec2(s, t));
        texCoords->push_back(osg::Vec2(0, t));
        quad->setTexCoordArray(0, texCoords);
    }
    static const unsigned short corners[] = {0, 1, 2, 0, 2, 3};
    quad->addPrimitiveSet(new osg::DrawElementsUShort(GL_TRIANGLES, 6, corners));
    quad->getOrCreateStateSet()->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
    return quad;
}

// The wall's front face as a quad facing the eye (y = 20).
osg::ref_ptr<osg::Geometry> wallQuad(const Vec4& colour = WallColour, float s = 0.f, float t = 1.f)
{
    return makeQuad(Vec3(-8, 20, -6), Vec3(8, 20, -6), Vec3(8, 20, 6), Vec3(-8, 20, 6), colour, s, t);
}

// The base scene's parts (SameImagePatterns.h): every box in its own geode, the wall under an
// identity transform.
struct Base
{
    osg::ref_ptr<osg::Geometry> wall;
    osg::ref_ptr<osg::Geode> wallGeode;
    osg::ref_ptr<osg::MatrixTransform> wallTransform;
    std::vector<osg::ref_ptr<osg::Geode>> boxes;     // every box, hidden ones first
    std::vector<osg::ref_ptr<osg::Geode>> hidden;    // the 3 × 3 grid behind the wall (and the far box)
    osg::ref_ptr<osg::Geode> inFront;                // the box in front of the wall
};

Base makeBase()
{
    Base base;
    base.wall = makeBox(Vec3(-8, 20, -6), Vec3(8, 21, 6), WallColour);
    base.wallGeode = geodeOf(base.wall);
    base.wallTransform = new osg::MatrixTransform;
    base.wallTransform->addChild(base.wallGeode);
    unsigned colour = 0;
    for (float z : {-4.f, 0.f, 4.f})
        for (float x : {-5.f, 0.f, 5.f})
            base.hidden.push_back(boxAt(Vec3(x, 40, z), 1.f, colourOf(colour++)));
    base.hidden.push_back(boxAt(Vec3(0, 90, 0), 4.f, colourOf(colour++)));
    base.boxes = base.hidden;
    base.boxes.push_back(boxAt(Vec3(16, 40, 0), 1.f, colourOf(colour++)));   // peeks past the wall's edge
    base.inFront = boxAt(Vec3(-4, 14, -3), 1.f, colourOf(colour++));
    base.boxes.push_back(base.inFront);
    base.boxes.push_back(boxAt(Vec3(12.5f, 26, -2), 1.f, colourOf(colour++))); // beside the wall
    base.boxes.push_back(boxAt(Vec3(0, -20, 0), 1.f, colourOf(colour++)));    // behind the eye
    base.boxes.push_back(boxAt(Vec3(-60, 20, 0), 1.f, colourOf(colour++)));   // far left
    base.boxes.push_back(boxAt(Vec3(0, 30, 40), 1.f, colourOf(colour++)));    // far above
    return base;
}

enum class Wall
{
    First, // drawn before the boxes (it hides them in the depth buffer)
    Last,  // drawn after them (what blending shows)
    None
};

void addBase(osg::Group& group, const Base& base, Wall wall = Wall::First)
{
    if (wall == Wall::First)
        group.addChild(base.wallTransform);
    for (const auto& box : base.boxes)
        group.addChild(box);
    if (wall == Wall::Last)
        group.addChild(base.wallTransform);
}

// The eye's path and gaze: small moves and turns every frame, always where the wall hides the grid.
Vec3 eyeAt(unsigned f)
{
    return Vec3(float(1.5 * std::sin(0.37 * f)), float(0.5 * std::sin(0.23 * f)), float(0.8 * std::sin(0.29 * f + 1.0)));
}
double yawAt(unsigned f) { return 5.0 * std::sin(0.31 * f); }
double pitchAt(unsigned f) { return 3.0 * std::sin(0.19 * f + 0.5); }

// The view from `eye` turned by `yaw` (degrees, to +x) and `pitch` (up) from +y, rolled by `roll`.
osg::Matrixd lookFrom(const osg::Vec3d& eye, double yaw, double pitch, double roll = 0.0)
{
    const double y = osg::DegreesToRadians(yaw), p = osg::DegreesToRadians(pitch);
    const osg::Vec3d direction(std::sin(y) * std::cos(p), std::cos(y) * std::cos(p), std::sin(p));
    const osg::Vec3d up = osg::Matrixd::rotate(osg::DegreesToRadians(roll), direction).preMult(osg::Vec3d(0, 0, 1));
    return osg::Matrixd::lookAt(eye, eye + direction, up);
}

osg::Camera& cameraOf(osgViewer::Viewer& viewer) { return *viewer.getCamera(); }

// The scene: `root`, the standard view, nothing animated.
Scene sceneOf(osg::Node* root)
{
    Scene scene;
    scene.root = root;
    scene.view = standardView;
    scene.animate = [](unsigned) {};
    return scene;
}

// A scene whose view is the standard path moved by `offset(frame)`.
std::function<void(osgViewer::Viewer&, unsigned)> viewMovedBy(std::function<Vec3(unsigned)> offset)
{
    return [offset](osgViewer::Viewer& viewer, unsigned f) {
        cameraOf(viewer).setViewMatrix(lookFrom(eyeAt(f) + offset(f), yawAt(f), pitchAt(f)));
    };
}

// A group `parent` with the state set `state` over `child`.
osg::ref_ptr<osg::Group> parentWith(osg::StateSet* state, osg::Node* child)
{
    osg::ref_ptr<osg::Group> parent = new osg::Group;
    parent->setStateSet(state);
    parent->addChild(child);
    return parent;
}

osg::ref_ptr<osg::StateSet> stateWith(osg::StateAttribute* attribute,
                                      osg::StateAttribute::GLModeValue value = osg::StateAttribute::ON)
{
    osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
    state->setAttributeAndModes(attribute, value);
    return state;
}

void setColour(osg::Geometry& geometry, const Vec4& colour)
{
    osg::ref_ptr<osg::Vec4Array> colours = new osg::Vec4Array;
    colours->push_back(colour);
    geometry.setColorArray(colours, osg::Array::BIND_OVERALL);
}

// An 8 × 8 texture of slats: the left four texels of each row opaque, the right four fully
// transparent; nearest filtering, repeated.
osg::ref_ptr<osg::Texture2D> slatTexture()
{
    osg::ref_ptr<osg::Image> image = new osg::Image;
    image->allocateImage(8, 8, 1, GL_RGBA, GL_UNSIGNED_BYTE);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
        {
            unsigned char* p = image->data(x, y);
            p[0] = 200;
            p[1] = 150;
            p[2] = 60;
            p[3] = x < 4 ? 255 : 0;
        }
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D(image);
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    texture->setWrap(osg::Texture::WRAP_S, osg::Texture::REPEAT);
    texture->setWrap(osg::Texture::WRAP_T, osg::Texture::REPEAT);
    return texture;
}

// A fence in the wall's place: a quad with slats 1 m wide and gaps 1 m wide (eight texture repeats
// over its 16 m; about six pixels each from the eye's path).
osg::ref_ptr<osg::Geometry> fence()
{
    osg::ref_ptr<osg::Geometry> quad = wallQuad(Vec4(1, 1, 1, 1), 8.f, 6.f);
    quad->getOrCreateStateSet()->setTextureAttributeAndModes(0, slatTexture(), osg::StateAttribute::ON);
    return quad;
}

// A colour texture a camera renders into, the frame's size, nearest filtering.
osg::ref_ptr<osg::Texture2D> renderTexture()
{
    osg::ref_ptr<osg::Texture2D> texture = new osg::Texture2D;
    texture->setTextureSize(int(Width), int(Height));
    texture->setInternalFormat(GL_RGBA);
    texture->setFilter(osg::Texture::MIN_FILTER, osg::Texture::NEAREST);
    texture->setFilter(osg::Texture::MAG_FILTER, osg::Texture::NEAREST);
    return texture;
}

// A quad in front of the wall, lower left of the view, showing `texture`; node mask 0x4.
osg::ref_ptr<osg::Geode> screenShowing(osg::Texture2D* texture)
{
    osg::ref_ptr<osg::Geometry> quad =
        makeQuad(Vec3(-5, 10, -3.5f), Vec3(-0.5f, 10, -3.5f), Vec3(-0.5f, 10, 0), Vec3(-5, 10, 0), Vec4(1, 1, 1, 1), 1.f, 1.f);
    quad->getOrCreateStateSet()->setTextureAttributeAndModes(0, texture, osg::StateAttribute::ON);
    osg::ref_ptr<osg::Geode> screen = geodeOf(quad);
    screen->setNodeMask(0x4);
    return screen;
}

// A camera that renders to `texture` before the main view (a frame buffer object).
void renderToTexture(osg::Camera& camera, osg::Texture2D* texture)
{
    camera.setRenderOrder(osg::Camera::PRE_RENDER);
    camera.setRenderTargetImplementation(osg::Camera::FRAME_BUFFER_OBJECT);
    camera.attach(osg::Camera::COLOR_BUFFER, texture);
    camera.setViewport(0, 0, int(Width), int(Height));
    camera.setClearColor(Vec4(0.1f, 0.1f, 0.2f, 1.f));
    camera.setClearMask(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// Each cull visitor of the viewer's cameras (master and slaves, both SceneViews of each).
void forEachCullVisitor(osgViewer::Viewer& viewer, const std::function<void(osgUtil::CullVisitor&)>& apply)
{
    osgViewer::Viewer::Cameras cameras;
    viewer.getCameras(cameras);
    for (osg::Camera* camera : cameras)
        if (auto* renderer = dynamic_cast<osgViewer::Renderer*>(camera->getRenderer()))
            for (unsigned i = 0; i < 2; ++i)
                if (osgUtil::SceneView* sceneView = renderer->getSceneView(i))
                    if (osgUtil::CullVisitor* cv = sceneView->getCullVisitor())
                        apply(*cv);
}

unsigned frameNumberOf(const osg::NodeVisitor* nv)
{
    return nv && nv->getFrameStamp() ? nv->getFrameStamp()->getFrameNumber() : 0u;
}

// A transform that follows the eye, as osghangglide's sky does (cull-time placement).
class FollowTheEye : public osg::Transform
{
public:
    bool computeLocalToWorldMatrix(osg::Matrix& matrix, osg::NodeVisitor* nv) const override
    {
        if (const osgUtil::CullVisitor* cv = nv ? nv->asCullVisitor() : nullptr)
        {
            const Vec3 eye = cv->getEyeLocal();
            if (_referenceFrame == RELATIVE_RF)
                matrix.preMultTranslate(eye);
            else
                matrix.makeTranslate(eye);
        }
        return true;
    }
    bool computeWorldToLocalMatrix(osg::Matrix& matrix, osg::NodeVisitor* nv) const override
    {
        if (const osgUtil::CullVisitor* cv = nv ? nv->asCullVisitor() : nullptr)
        {
            const Vec3 eye = cv->getEyeLocal();
            if (_referenceFrame == RELATIVE_RF)
                matrix.postMultTranslate(-eye);
            else
                matrix.makeTranslate(-eye);
        }
        return true;
    }
};

// Cull callback: on odd frames traverses every child but the first.
struct SkipFirstChildOnOddFrames : osg::NodeCallback
{
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        osg::Group* group = node->asGroup();
        if (group && frameNumberOf(nv) % 2 == 1)
        {
            for (unsigned i = 1; i < group->getNumChildren(); ++i)
                group->getChild(i)->accept(*nv);
            return;
        }
        traverse(node, nv);
    }
};

// Cull callback: sets its MatrixTransform's matrix from the frame number, then traverses.
struct MoveWhileCulling : osg::NodeCallback
{
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        if (auto* transform = dynamic_cast<osg::MatrixTransform*>(node))
            transform->setMatrix(osg::Matrixd::translate(11.0 * std::sin(0.4 * frameNumberOf(nv)), 0, 0));
        traverse(node, nv);
    }
};

// Update callback: slides its MatrixTransform from behind the wall out past its right edge.
struct SlideOut : osg::NodeCallback
{
    void operator()(osg::Node* node, osg::NodeVisitor* nv) override
    {
        if (auto* transform = dynamic_cast<osg::MatrixTransform*>(node))
            transform->setMatrix(osg::Matrixd::translate(-2.0 + 0.7 * frameNumberOf(nv), 40, 1));
        traverse(node, nv);
    }
};

// Draw callback: draws the drawable on even frames only.
struct DrawOnEvenFrames : osg::Drawable::DrawCallback
{
    void drawImplementation(osg::RenderInfo& renderInfo, const osg::Drawable* drawable) const override
    {
        const osg::FrameStamp* stamp = renderInfo.getState()->getFrameStamp();
        if (!stamp || stamp->getFrameNumber() % 2 == 0)
            drawable->drawImplementation(renderInfo);
    }
};

// Draw callback: draws the drawable with the depth test off, behind OSG's back.
struct DrawOverEverything : osg::Drawable::DrawCallback
{
    void drawImplementation(osg::RenderInfo& renderInfo, const osg::Drawable* drawable) const override
    {
        glDisable(GL_DEPTH_TEST);
        drawable->drawImplementation(renderInfo);
        glEnable(GL_DEPTH_TEST);
    }
};

using Patterns = std::vector<Pattern>;

void add(Patterns& patterns, std::string name, std::string what, std::function<Scene(const Build&)> build,
         bool checksCulling = false)
{
    patterns.push_back(Pattern{std::move(name), std::move(what), std::move(build), checksCulling});
}

// ---------------------------------------------------------------------------------------------------
// The patterns the issue names first: decisions OSG takes from above the group.

void cameraAndStatePatterns(Patterns& p)
{
    add(p, "base", "the base scene: a wall hides a grid of boxes, the eye moves and turns", [](const Build& b) {
        addBase(*b.group, makeBase());
        return sceneOf(b.group);
    }, true);

    add(p, "cull_mask_leaves_wall_out", "wall node mask 0x2, camera cull mask 0x1: the boxes behind show",
        [](const Build& b) {
            const Base base = makeBase();
            base.wallTransform->setNodeMask(0x2);
            addBase(*b.group, base);
            Scene scene = sceneOf(b.group);
            scene.setUpViewer = [](osgViewer::Viewer& viewer) { cameraOf(viewer).setCullMask(0x1); };
            return scene;
        });

    add(p, "polygon_mode_line_on_camera", "PolygonMode LINE on the camera's state set", [](const Build& b) {
        addBase(*b.group, makeBase());
        Scene scene = sceneOf(b.group);
        scene.setUpViewer = [](osgViewer::Viewer& viewer) {
            cameraOf(viewer).getOrCreateStateSet()->setAttributeAndModes(
                new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::LINE));
        };
        return scene;
    });

    add(p, "depth_writes_off_on_parent", "osg::Depth with write mask false on a parent of the group",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            return sceneOf(parentWith(stateWith(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false)), b.group));
        });

    add(p, "depth_test_off_in_later_bin", "a box behind the wall drawn without the depth test in render bin 10",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Geode> marker = boxAt(Vec3(2, 45, 2), 1.5f, Vec4(1, 0.5f, 0, 1));
            marker->getOrCreateStateSet()->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
            marker->getOrCreateStateSet()->setRenderBinDetails(10, "RenderBin");
            b.group->addChild(marker);
            return sceneOf(b.group);
        });

    add(p, "computed_near_far_far_box",
        "near/far computed by OSG from bounding volumes; the projection's far plane (50) is nearer than an "
        "unoccluded box in view (y = 120, above the wall)",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            b.group->addChild(boxAt(FarBoxInView, 4.f, Vec4(1, 1, 1, 1)));
            Scene scene = sceneOf(b.group);
            scene.setUpViewer = [](osgViewer::Viewer& viewer) {
                osg::Camera& camera = cameraOf(viewer);
                camera.setComputeNearFarMode(osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES);
                camera.setProjectionMatrixAsPerspective(45.0, Aspect, 1.0, 50.0);
            };
            return scene;
        });

    add(p, "near_far_from_primitives", "near/far computed by OSG from primitives; projection far plane 30",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            b.group->addChild(boxAt(FarBoxInView, 4.f, Vec4(1, 1, 1, 1)));
            Scene scene = sceneOf(b.group);
            scene.setUpViewer = [](osgViewer::Viewer& viewer) {
                osg::Camera& camera = cameraOf(viewer);
                camera.setComputeNearFarMode(osg::CullSettings::COMPUTE_NEAR_FAR_USING_PRIMITIVES);
                camera.setProjectionMatrixAsPerspective(45.0, Aspect, 1.0, 30.0);
            };
            return scene;
        });

    add(p, "default_camera_scene_beyond_far_eye_backs_away",
        "osgViewer's default near/far (computed) on a scene larger than the projection's far plane (60), the eye "
        "backing away 5 m a frame",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            b.group->addChild(boxAt(Vec3(-20, 150, 0), 6.f, Vec4(1, 1, 1, 1)));
            b.group->addChild(boxAt(Vec3(25, 220, 10), 8.f, Vec4(0.8f, 0.4f, 0.1f, 1)));
            b.group->addChild(boxAt(Vec3(0, 320, -20), 10.f, Vec4(0.3f, 0.9f, 0.9f, 1)));
            Scene scene = sceneOf(b.group);
            scene.setUpViewer = [](osgViewer::Viewer& viewer) {
                osg::Camera& camera = cameraOf(viewer);
                camera.setComputeNearFarMode(osg::CullSettings::COMPUTE_NEAR_FAR_USING_BOUNDING_VOLUMES);
                camera.setProjectionMatrixAsPerspective(30.0, Aspect, 1.0, 60.0);
            };
            scene.view = viewMovedBy([](unsigned f) { return Vec3(0, -5.f * float(f), 0); });
            return scene;
        });

    add(p, "eye_following_sky",
        "an osg::Transform subclass following the eye (getEyeLocal, osghangglide's sky), culling inactive, holding a "
        "sky box around the eye drawn first without depth writes",
        [](const Build& b) {
            osg::ref_ptr<osg::Geode> sky = boxAt(Vec3(), 60.f, Vec4(0.15f, 0.2f, 0.45f, 1));
            osg::StateSet* state = sky->getOrCreateStateSet();
            state->setRenderBinDetails(-1, "RenderBin");
            state->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS, 1.0, 1.0, false));
            osg::ref_ptr<FollowTheEye> follow = new FollowTheEye;
            follow->setCullingActive(false);
            follow->addChild(sky);
            b.group->addChild(follow);
            addBase(*b.group, makeBase());
            return sceneOf(b.group);
        });

    add(p, "camera_state_set_changed_at_run_time", "wire-frame on the camera's state set from frame 10 to 19",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            Scene scene = sceneOf(b.group);
            scene.view = [](osgViewer::Viewer& viewer, unsigned f) {
                standardView(viewer, f);
                osg::StateSet* state = cameraOf(viewer).getOrCreateStateSet();
                if (f >= 10 && f < 20)
                    state->setAttributeAndModes(
                        new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::LINE));
                else
                    state->removeAttribute(osg::StateAttribute::POLYGONMODE);
            };
            return scene;
        });

    add(p, "view_frustum_culling_mode",
        "camera culling mode VIEW_FRUSTUM_CULLING: no small-feature culling, near and far planes culled (far 40)",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            Scene scene = sceneOf(b.group);
            scene.setUpViewer = [](osgViewer::Viewer& viewer) {
                osg::Camera& camera = cameraOf(viewer);
                camera.setCullingMode(osg::CullSettings::VIEW_FRUSTUM_CULLING);
                camera.setProjectionMatrixAsPerspective(45.0, Aspect, 1.0, 40.0);
            };
            return scene;
        });

    add(p, "default_culling_mode_small_features",
        "camera culling mode DEFAULT_CULLING (small-feature culling on) with boxes 0.2 to 4 pixels wide below the "
        "wall",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            for (int i = 0; i < 7; ++i)
                b.group->addChild(boxAt(Vec3(-6.f + 2.f * float(i), 30.f, -10.5f), 0.03f + 0.07f * float(i),
                                        colourOf(unsigned(i) + 3)));
            Scene scene = sceneOf(b.group);
            scene.setUpViewer = [](osgViewer::Viewer& viewer) {
                cameraOf(viewer).setCullingMode(osg::CullSettings::DEFAULT_CULLING);
            };
            return scene;
        });

    add(p, "orthographic_camera", "an orthographic projection 48 m × 36 m", [](const Build& b) {
        addBase(*b.group, makeBase());
        Scene scene = sceneOf(b.group);
        scene.setUpViewer = [](osgViewer::Viewer& viewer) {
            cameraOf(viewer).setProjectionMatrixAsOrtho(-24, 24, -18, 18, 1, 200);
        };
        return scene;
    });

    add(p, "off_centre_projection", "an asymmetric (off-centre) perspective frustum", [](const Build& b) {
        addBase(*b.group, makeBase());
        Scene scene = sceneOf(b.group);
        scene.setUpViewer = [](osgViewer::Viewer& viewer) {
            cameraOf(viewer).setProjectionMatrixAsFrustum(-0.25, 0.55, -0.35, 0.25, 1.0, 200.0);
        };
        return scene;
    });

    add(p, "zoom_field_of_view", "the vertical field of view changes every frame, 20° to 70°", [](const Build& b) {
        addBase(*b.group, makeBase());
        Scene scene = sceneOf(b.group);
        scene.view = [](osgViewer::Viewer& viewer, unsigned f) {
            standardView(viewer, f);
            cameraOf(viewer).setProjectionMatrixAsPerspective(45.0 + 25.0 * std::sin(0.4 * f), Aspect, 1.0, 200.0);
        };
        return scene;
    });

    add(p, "viewport_resized", "the viewport shrinks to 64 × 80 at (8, 8) from frame 10 to 19, projection to match",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            Scene scene = sceneOf(b.group);
            const auto resized = [](unsigned f) { return f >= 10 && f < 20; };
            scene.view = [resized](osgViewer::Viewer& viewer, unsigned f) {
                standardView(viewer, f);
                osg::Camera& camera = cameraOf(viewer);
                if (resized(f))
                {
                    camera.setViewport(8, 8, 64, 80);
                    camera.setProjectionMatrixAsPerspective(45.0, 64.0 / 80.0, 1.0, 200.0);
                }
                else
                {
                    camera.setViewport(0, 0, int(Width), int(Height));
                    camera.setProjectionMatrixAsPerspective(45.0, Aspect, 1.0, 200.0);
                }
            };
            scene.comparedRegion = [resized](unsigned f) {
                return resized(f) ? osg::Vec4i(8, 8, 64, 80) : osg::Vec4i(0, 0, int(Width), int(Height));
            };
            return scene;
        });

    add(p, "gaze_jittered", "the eye stays, the gaze jumps up to 20° in every direction and rolls every frame",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            Scene scene = sceneOf(b.group);
            scene.view = [](osgViewer::Viewer& viewer, unsigned f) {
                cameraOf(viewer).setViewMatrix(lookFrom(Vec3(0.3f, 0, -0.2f), 20.0 * std::sin(1.7 * f),
                                                        15.0 * std::cos(2.3 * f), 25.0 * std::sin(0.9 * f)));
            };
            return scene;
        });

    add(p, "eye_passes_through_wall", "the eye walks through the wall (y from -2 to 36)", [](const Build& b) {
        addBase(*b.group, makeBase());
        Scene scene = sceneOf(b.group);
        scene.view = viewMovedBy([](unsigned f) { return Vec3(0, -2.f + 1.3f * float(f), 0); });
        return scene;
    });

    add(p, "node_mask_override_on_cull_visitor",
        "the cull visitors' node mask override 0xffffffff (as osgUtil::Optimizer's): the wall and a box with node "
        "mask 0 are drawn all the same",
        [](const Build& b) {
            const Base base = makeBase();
            base.wallTransform->setNodeMask(0);
            base.inFront->setNodeMask(0);
            addBase(*b.group, base);
            Scene scene = sceneOf(b.group);
            scene.view = [](osgViewer::Viewer& viewer, unsigned f) {
                standardView(viewer, f);
                forEachCullVisitor(viewer, [](osgUtil::CullVisitor& cv) { cv.setNodeMaskOverride(0xffffffff); });
            };
            return scene;
        });

    add(p, "lod_scale_on_camera", "an LOD over the wall; the camera's LOD scale changes every frame (0.5 to 2)",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::LOD> lod = new osg::LOD;
            lod->addChild(base.wallTransform, 0.f, 32.f);
            lod->addChild(boxAt(Vec3(0, 20.5f, 0), 1.f, WallColour), 32.f, 1e7f);
            b.group->addChild(lod);
            addBase(*b.group, base, Wall::None);
            Scene scene = sceneOf(b.group);
            scene.view = [](osgViewer::Viewer& viewer, unsigned f) {
                standardView(viewer, f);
                cameraOf(viewer).setLODScale(float(0.5 + 1.5 * ((f * 7) % 10) / 9.0));
            };
            return scene;
        });
}

// ---------------------------------------------------------------------------------------------------
// State on the wall, on a parent, on one box.

void statePatterns(Patterns& p)
{
    add(p, "wall_state_edited_in_place", "PolygonMode LINE added to and removed from the wall's own state set",
        [](const Build& b) {
            const Base base = makeBase();
            addBase(*b.group, base);
            Scene scene = sceneOf(b.group);
            osg::ref_ptr<osg::StateSet> state = base.wall->getOrCreateStateSet();
            scene.animate = [state](unsigned f) {
                if ((f / 5) % 2 == 1)
                    state->setAttributeAndModes(
                        new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::LINE));
                else
                    state->removeAttribute(osg::StateAttribute::POLYGONMODE);
            };
            return scene;
        });

    add(p, "wall_given_new_state_set", "a new StateSet assigned to the wall every 4 frames, wire-frame every other one",
        [](const Build& b) {
            const Base base = makeBase();
            addBase(*b.group, base);
            Scene scene = sceneOf(b.group);
            osg::ref_ptr<osg::Geometry> wall = base.wall;
            scene.animate = [wall](unsigned f) {
                if (f % 4 != 0)
                    return;
                osg::ref_ptr<osg::StateSet> state = new osg::StateSet;
                state->setMode(GL_LIGHTING, osg::StateAttribute::OFF);
                if ((f / 4) % 2 == 1)
                    state->setAttributeAndModes(
                        new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::LINE));
                wall->setStateSet(state);
            };
            return scene;
        });

    add(p, "overriding_state_on_parent",
        "PolygonMode LINE with OVERRIDE on a parent of the group; the wall's own state asks for FILL",
        [](const Build& b) {
            const Base base = makeBase();
            base.wall->getOrCreateStateSet()->setAttributeAndModes(
                new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::FILL));
            addBase(*b.group, base);
            return sceneOf(parentWith(
                stateWith(new osg::PolygonMode(osg::PolygonMode::FRONT_AND_BACK, osg::PolygonMode::LINE),
                          osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE),
                b.group));
        });

    add(p, "clip_node_above_group", "a ClipNode above the group whose plane cuts the wall's left half away",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::ClipNode> clip = new osg::ClipNode;
            clip->addClipPlane(new osg::ClipPlane(0, 1.0, 10.0, 0.0, -210.0)); // keeps x + 10 (y - 21) ≥ 0
            clip->addChild(b.group);
            return sceneOf(clip);
        });

    add(p, "clip_node_over_wall", "a ClipNode inside the group over the wall only, cutting its left half away",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::ClipNode> clip = new osg::ClipNode;
            clip->addClipPlane(new osg::ClipPlane(0, 1.0, 10.0, 0.0, -210.0));
            clip->addChild(base.wallTransform);
            b.group->addChild(clip);
            addBase(*b.group, base, Wall::None);
            return sceneOf(b.group);
        });

    add(p, "alpha_tested_fence", "a fence of slats (texture alpha, GL_ALPHA_TEST with AlphaFunc GREATER 0.5)",
        [](const Build& b) {
            osg::ref_ptr<osg::Geometry> slats = fence();
            osg::StateSet* state = slats->getOrCreateStateSet();
            state->setAttributeAndModes(new osg::AlphaFunc(osg::AlphaFunc::GREATER, 0.5f));
            b.group->addChild(geodeOf(slats));
            addBase(*b.group, makeBase(), Wall::None);
            return sceneOf(b.group);
        });

    add(p, "alpha_to_coverage_fence",
        "the fence with GL_SAMPLE_ALPHA_TO_COVERAGE_ARB on a 4-sample context (no blending, no alpha test)",
        [](const Build& b) {
            osg::ref_ptr<osg::Geometry> slats = fence();
            slats->getOrCreateStateSet()->setMode(GL_SAMPLE_ALPHA_TO_COVERAGE_ARB, osg::StateAttribute::ON);
            b.group->addChild(geodeOf(slats));
            addBase(*b.group, makeBase(), Wall::None);
            Scene scene = sceneOf(b.group);
            scene.samples = 4;
            return scene;
        });

    add(p, "transparent_wall", "the wall blended (alpha 0.5) in the TRANSPARENT_BIN", [](const Build& b) {
        const Base base = makeBase();
        setColour(*base.wall, Vec4(0.6f, 0.6f, 0.6f, 0.5f));
        osg::StateSet* state = base.wall->getOrCreateStateSet();
        state->setAttributeAndModes(new osg::BlendFunc(osg::BlendFunc::SRC_ALPHA, osg::BlendFunc::ONE_MINUS_SRC_ALPHA));
        state->setRenderingHint(osg::StateSet::TRANSPARENT_BIN);
        addBase(*b.group, base);
        return sceneOf(b.group);
    });

    add(p, "blending_on_parent", "blending on a parent of the group; the wall (alpha 0.5) drawn last in the opaque bin",
        [](const Build& b) {
            const Base base = makeBase();
            setColour(*base.wall, Vec4(0.6f, 0.6f, 0.6f, 0.5f));
            addBase(*b.group, base, Wall::Last);
            return sceneOf(parentWith(
                stateWith(new osg::BlendFunc(osg::BlendFunc::SRC_ALPHA, osg::BlendFunc::ONE_MINUS_SRC_ALPHA)), b.group));
        });

    add(p, "colour_mask_off_wall", "ColorMask all false on the wall (invisible, still writes depth)",
        [](const Build& b) {
            const Base base = makeBase();
            base.wall->getOrCreateStateSet()->setAttributeAndModes(new osg::ColorMask(false, false, false, false));
            addBase(*b.group, base);
            return sceneOf(b.group);
        });

    add(p, "colour_mask_and_depth_writes_off_wall", "ColorMask false and depth writes off on the wall (draws nothing)",
        [](const Build& b) {
            const Base base = makeBase();
            osg::StateSet* state = base.wall->getOrCreateStateSet();
            state->setAttributeAndModes(new osg::ColorMask(false, false, false, false));
            state->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false));
            addBase(*b.group, base);
            return sceneOf(b.group);
        });

    add(p, "scissor_on_parent", "osg::Scissor (left 80 columns) on a parent of the group", [](const Build& b) {
        addBase(*b.group, makeBase());
        return sceneOf(parentWith(stateWith(new osg::Scissor(0, 0, 80, int(Height))), b.group));
    });

    add(p, "program_on_parent_discards",
        "an osg::Program on a parent of the group; its fragment shader discards a checkerboard of the wall "
        "(a uniform set on the wall)",
        [](const Build& b) {
            const Base base = makeBase();
            base.wall->getOrCreateStateSet()->addUniform(new osg::Uniform("holes", true));
            addBase(*b.group, base);
            osg::ref_ptr<osg::Program> program = new osg::Program;
            program->addShader(new osg::Shader(osg::Shader::VERTEX, "#version 120\n"
                                                                    "void main() {\n"
                                                                    "    gl_Position = ftransform();\n"
                                                                    "    gl_FrontColor = gl_Color;\n"
                                                                    "    gl_BackColor = gl_Color;\n"
                                                                    "}\n"));
            program->addShader(new osg::Shader(osg::Shader::FRAGMENT,
                                               "#version 120\n"
                                               "uniform bool holes;\n"
                                               "void main() {\n"
                                               "    vec2 cell = floor(gl_FragCoord.xy / 4.0);\n"
                                               "    if (holes && mod(cell.x + cell.y, 2.0) < 1.0) discard;\n"
                                               "    gl_FragColor = gl_Color;\n"
                                               "}\n"));
            osg::ref_ptr<osg::StateSet> state = stateWith(program);
            state->addUniform(new osg::Uniform("holes", false));
            return sceneOf(parentWith(state, b.group));
        });

    add(p, "stencil_on_parent",
        "stencil test EQUAL 0 on a parent of the group; an invisible quad (colour and depth writes off, bin -1) "
        "writes 1 in the middle of the wall; the boxes draw with the stencil test off",
        [](const Build& b) {
            const Base base = makeBase();
            for (const auto& box : base.boxes)
                box->getDrawable(0)->getOrCreateStateSet()->setMode(GL_STENCIL_TEST, osg::StateAttribute::OFF);
            osg::ref_ptr<osg::Geometry> writer =
                makeQuad(Vec3(-3, 15, -2), Vec3(3, 15, -2), Vec3(3, 15, 2), Vec3(-3, 15, 2), Vec4(1, 1, 1, 1));
            osg::StateSet* state = writer->getOrCreateStateSet();
            state->setRenderBinDetails(-1, "RenderBin");
            state->setAttributeAndModes(new osg::ColorMask(false, false, false, false));
            state->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 1.0, false));
            osg::ref_ptr<osg::Stencil> write = new osg::Stencil;
            write->setFunction(osg::Stencil::ALWAYS, 1, ~0u);
            write->setOperation(osg::Stencil::REPLACE, osg::Stencil::REPLACE, osg::Stencil::REPLACE);
            state->setAttributeAndModes(write);
            b.group->addChild(geodeOf(writer));
            addBase(*b.group, base);
            osg::ref_ptr<osg::Stencil> test = new osg::Stencil;
            test->setFunction(osg::Stencil::EQUAL, 0, ~0u);
            test->setOperation(osg::Stencil::KEEP, osg::Stencil::KEEP, osg::Stencil::KEEP);
            Scene scene = sceneOf(parentWith(stateWith(test), b.group));
            scene.stencilBits = 8;
            scene.setUpViewer = [](osgViewer::Viewer& viewer) {
                osg::Camera& camera = cameraOf(viewer);
                camera.setClearMask(camera.getClearMask() | GL_STENCIL_BUFFER_BIT);
                camera.setClearStencil(0);
            };
            return scene;
        });

    add(p, "depth_function_always_box", "a box behind the wall with depth function ALWAYS, after the wall",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Geode> box = boxAt(Vec3(3, 45, -2), 1.5f, Vec4(1, 0.5f, 0, 1));
            box->getOrCreateStateSet()->setAttributeAndModes(new osg::Depth(osg::Depth::ALWAYS));
            b.group->addChild(box);
            return sceneOf(b.group);
        });

    add(p, "depth_function_greater_box", "a box behind the wall with depth function GREATER, after the wall",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Geode> box = boxAt(Vec3(-3, 45, 2), 1.5f, Vec4(1, 0.5f, 0, 1));
            box->getOrCreateStateSet()->setAttributeAndModes(new osg::Depth(osg::Depth::GREATER));
            b.group->addChild(box);
            return sceneOf(b.group);
        });

    add(p, "depth_range_box", "a box behind the wall drawn with depth range [0, 0.05] (a first-person weapon's way)",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Geode> box = boxAt(Vec3(2, 45, 1), 1.5f, Vec4(1, 0.5f, 0, 1));
            box->getOrCreateStateSet()->setAttributeAndModes(new osg::Depth(osg::Depth::LESS, 0.0, 0.05));
            b.group->addChild(box);
            return sceneOf(b.group);
        });

    add(p, "vertex_shader_moves_wall",
        "the wall drawn by its own osg::Program whose vertex shader slides it sideways (a uniform set every frame, "
        "as hardware skinning does); its initial bound covers the whole sweep",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::Program> program = new osg::Program;
            program->addShader(new osg::Shader(osg::Shader::VERTEX, "#version 120\n"
                                                                    "uniform vec3 offset;\n"
                                                                    "void main() {\n"
                                                                    "    gl_Position = gl_ModelViewProjectionMatrix *\n"
                                                                    "                  (gl_Vertex + vec4(offset, 0.0));\n"
                                                                    "    gl_FrontColor = gl_Color;\n"
                                                                    "    gl_BackColor = gl_Color;\n"
                                                                    "}\n"));
            program->addShader(new osg::Shader(osg::Shader::FRAGMENT, "#version 120\n"
                                                                      "void main() { gl_FragColor = gl_Color; }\n"));
            osg::ref_ptr<osg::Uniform> offset = new osg::Uniform("offset", Vec3());
            osg::StateSet* state = base.wall->getOrCreateStateSet();
            state->setAttributeAndModes(program);
            state->addUniform(offset);
            base.wall->setInitialBound(osg::BoundingBox(Vec3(-21, 20, -6), Vec3(21, 21, 6)));
            addBase(*b.group, base);
            Scene scene = sceneOf(b.group);
            scene.animate = [offset](unsigned f) { offset->set(Vec3(float(13.0 * std::sin(0.21 * f)), 0, 0)); };
            return scene;
        });

    add(p, "reversed_depth_on_camera",
        "reversed depth: the camera clears depth to 0, its state set has Depth GREATER with depth range [1, 0]",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            Scene scene = sceneOf(b.group);
            scene.setUpViewer = [](osgViewer::Viewer& viewer) {
                osg::Camera& camera = cameraOf(viewer);
                camera.setClearDepth(0.0);
                camera.getOrCreateStateSet()->setAttributeAndModes(new osg::Depth(osg::Depth::GREATER, 1.0, 0.0));
            };
            return scene;
        });

    add(p, "cull_face_front_wall", "the wall a single quad facing the eye, CullFace FRONT on it", [](const Build& b) {
        osg::ref_ptr<osg::Geometry> wall = wallQuad();
        wall->getOrCreateStateSet()->setAttributeAndModes(new osg::CullFace(osg::CullFace::FRONT));
        b.group->addChild(geodeOf(wall));
        addBase(*b.group, makeBase(), Wall::None);
        return sceneOf(b.group);
    });

    add(p, "decal_with_polygon_offset", "a decal in the wall's front plane, PolygonOffset(-1, -1), after the wall",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Geometry> decal =
                makeQuad(Vec3(-3, 20, -2), Vec3(3, 20, -2), Vec3(3, 20, 2), Vec3(-3, 20, 2), Vec4(0.9f, 0.1f, 0.5f, 1));
            decal->getOrCreateStateSet()->setAttributeAndModes(new osg::PolygonOffset(-1.f, -1.f));
            b.group->addChild(geodeOf(decal));
            return sceneOf(b.group);
        });
}

// ---------------------------------------------------------------------------------------------------
// A graph the application changes: occluders moved, hidden, switched, edited.

void changingGraphPatterns(Patterns& p)
{
    add(p, "wall_moved_by_matrix_transform", "the wall's MatrixTransform slides it sideways every frame",
        [](const Build& b) {
            const Base base = makeBase();
            addBase(*b.group, base);
            Scene scene = sceneOf(b.group);
            osg::ref_ptr<osg::MatrixTransform> wall = base.wallTransform;
            scene.animate = [wall](unsigned f) { wall->setMatrix(osg::Matrixd::translate(12.0 * std::sin(0.21 * f), 0, 0)); };
            return scene;
        });

    add(p, "wall_in_switch_toggled", "the wall under an osg::Switch turned off and on every 3 frames",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::Switch> toggle = new osg::Switch;
            toggle->addChild(base.wallTransform);
            b.group->addChild(toggle);
            addBase(*b.group, base, Wall::None);
            Scene scene = sceneOf(b.group);
            scene.animate = [toggle](unsigned f) { toggle->setValue(0, (f / 3) % 2 == 0); };
            return scene;
        });

    add(p, "wall_in_sequence", "an osg::Sequence alternating the wall and an empty group (0.1 s each, simulation time)",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::Sequence> sequence = new osg::Sequence;
            sequence->addChild(base.wallTransform, 0.1);
            sequence->addChild(new osg::Group, 0.1);
            sequence->setInterval(osg::Sequence::LOOP, 0, -1);
            sequence->setDuration(1.f, -1);
            sequence->setMode(osg::Sequence::START);
            b.group->addChild(sequence);
            addBase(*b.group, base, Wall::None);
            return sceneOf(b.group);
        });

    add(p, "wall_node_mask_toggled", "the wall's node mask 0 for two frames of every four", [](const Build& b) {
        const Base base = makeBase();
        addBase(*b.group, base);
        Scene scene = sceneOf(b.group);
        osg::ref_ptr<osg::MatrixTransform> wall = base.wallTransform;
        scene.animate = [wall](unsigned f) { wall->setNodeMask(f % 4 < 2 ? ~0u : 0u); };
        return scene;
    });

    add(p, "lod_crossed_by_eye_distance", "an LOD: the wall within 32 m, a small box beyond; the eye walks back and forth",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::LOD> lod = new osg::LOD;
            lod->addChild(base.wallTransform, 0.f, 32.f);
            lod->addChild(boxAt(Vec3(0, 20.5f, 0), 1.f, WallColour), 32.f, 1e7f);
            b.group->addChild(lod);
            addBase(*b.group, base, Wall::None);
            Scene scene = sceneOf(b.group);
            scene.view = viewMovedBy([](unsigned f) { return Vec3(0, float(-11.0 + 11.0 * std::cos(0.25 * f)), 0); });
            return scene;
        });

    add(p, "children_added_and_removed", "every frame the group's children are rebuilt: boxes and the wall come and go, "
                                         "a new box is made",
        [](const Build& b) {
            const Base base = makeBase();
            addBase(*b.group, base);
            Scene scene = sceneOf(b.group);
            osg::ref_ptr<osg::Group> group = b.group;
            // note: the boxes made are kept, never freed: OSG 3.6's osg::State skips binding a buffer
            // object whose address equals the one bound last, so a drawable freed and another allocated
            // at its address may be drawn from the stale binding, in either run, as malloc happens to
            // place it (seen as a missing or torn box in 1 run in 10, with identical visible sets)
            auto made = std::make_shared<std::vector<osg::ref_ptr<osg::Node>>>();
            scene.animate = [group, base, made](unsigned f) {
                group->removeChildren(0, group->getNumChildren());
                if ((f / 4) % 2 == 0)
                    group->addChild(base.wallTransform);
                for (unsigned i = 0; i < base.boxes.size(); ++i)
                    if ((f + i) % 3 != 0)
                        group->addChild(base.boxes[i]);
                made->push_back(boxAt(Vec3(-12.f + 0.8f * float(f), 30, -7), 1.f, colourOf(f)));
                group->addChild(made->back());
            };
            return scene;
        });

    add(p, "wall_vertices_edited_in_place", "the wall's vertex array moved sideways in place (dirty(), dirtyBound())",
        [](const Build& b) {
            const Base base = makeBase();
            addBase(*b.group, base);
            Scene scene = sceneOf(b.group);
            osg::ref_ptr<osg::Geometry> wall = base.wall;
            osg::ref_ptr<osg::Vec3Array> original =
                new osg::Vec3Array(*static_cast<osg::Vec3Array*>(wall->getVertexArray()), osg::CopyOp::DEEP_COPY_ALL);
            scene.animate = [wall, original](unsigned f) {
                auto* vertices = static_cast<osg::Vec3Array*>(wall->getVertexArray());
                const float shift = float(9.0 * std::sin(0.25 * f));
                for (std::size_t i = 0; i < vertices->size(); ++i)
                    (*vertices)[i] = (*original)[i] + Vec3(shift, 0, 0);
                vertices->dirty();
                wall->dirtyDisplayList();
                wall->dirtyBound();
            };
            return scene;
        });

    add(p, "position_attitude_transform_animated", "the wall under a PositionAttitudeTransform that slides and turns",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::PositionAttitudeTransform> pat = new osg::PositionAttitudeTransform;
            pat->addChild(geodeOf(makeBox(Vec3(-8, -0.5f, -6), Vec3(8, 0.5f, 6), WallColour)));
            b.group->addChild(pat);
            addBase(*b.group, base, Wall::None);
            Scene scene = sceneOf(b.group);
            scene.animate = [pat](unsigned f) {
                pat->setPosition(Vec3(float(6.0 * std::sin(0.2 * f)), 20.5f, 0));
                pat->setAttitude(osg::Quat(0.1 * f, osg::Vec3d(0, 0, 1)));
            };
            return scene;
        });

    add(p, "dynamic_wall_moving", "the wall's MatrixTransform has DYNAMIC data variance and bobs up and down",
        [](const Build& b) {
            const Base base = makeBase();
            base.wallTransform->setDataVariance(osg::Object::DYNAMIC);
            addBase(*b.group, base);
            Scene scene = sceneOf(b.group);
            osg::ref_ptr<osg::MatrixTransform> wall = base.wallTransform;
            scene.animate = [wall](unsigned f) { wall->setMatrix(osg::Matrixd::translate(0, 0, 9.0 * std::sin(0.35 * f))); };
            return scene;
        });

    add(p, "mirrored_scaled_wall", "the wall a unit box under a mirroring, non-uniformly scaling MatrixTransform",
        [](const Build& b) {
            osg::ref_ptr<osg::MatrixTransform> transform = new osg::MatrixTransform;
            transform->addChild(geodeOf(makeBox(Vec3(-1, -1, -1), Vec3(1, 1, 1), WallColour)));
            b.group->addChild(transform);
            addBase(*b.group, makeBase(), Wall::None);
            Scene scene = sceneOf(b.group);
            scene.animate = [transform](unsigned f) {
                transform->setMatrix(osg::Matrixd::scale(-(5.0 + 4.0 * std::sin(0.3 * f)), 0.5, 6.0) *
                                     osg::Matrixd::translate(0, 20.5, 0));
            };
            return scene;
        });

    add(p, "animation_path_callback", "an AnimationPathCallback (simulation time) swings the wall's transform",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::AnimationPath> path = new osg::AnimationPath;
            path->setLoopMode(osg::AnimationPath::LOOP);
            path->insert(0.0, osg::AnimationPath::ControlPoint(osg::Vec3d(-12, 0, 0)));
            path->insert(0.5, osg::AnimationPath::ControlPoint(osg::Vec3d(12, 0, 3)));
            path->insert(1.0, osg::AnimationPath::ControlPoint(osg::Vec3d(-12, 0, 0)));
            base.wallTransform->setUpdateCallback(new osg::AnimationPathCallback(path.get()));
            addBase(*b.group, base);
            return sceneOf(b.group);
        });

    add(p, "update_callback_moves_box", "an update callback slides a box from behind the wall past its edge",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::MatrixTransform> mover = new osg::MatrixTransform;
            mover->addChild(boxAt(Vec3(), 1.f, Vec4(1, 0.5f, 0, 1)));
            mover->setUpdateCallback(new SlideOut);
            b.group->addChild(mover);
            return sceneOf(b.group);
        });

    add(p, "cull_callback_skips_wall_on_odd_frames", "a cull callback that skips its first child (the wall) on odd frames",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::Group> walls = new osg::Group;
            walls->addChild(base.wallTransform);
            walls->addChild(base.inFront);
            walls->setCullCallback(new SkipFirstChildOnOddFrames);
            b.group->addChild(walls);
            for (const auto& box : base.boxes)
                if (box != base.inFront)
                    b.group->addChild(box);
            return sceneOf(b.group);
        });

    add(p, "cull_callback_moves_transform", "a cull callback sets the wall's matrix while it is culled",
        [](const Build& b) {
            const Base base = makeBase();
            base.wallTransform->setCullCallback(new MoveWhileCulling);
            addBase(*b.group, base);
            return sceneOf(b.group);
        });

    add(p, "draw_callback_skips_wall", "a draw callback that draws the wall on even frames only", [](const Build& b) {
        const Base base = makeBase();
        base.wall->setUseDisplayList(false); // a display list would record the callback's first draw for good
        base.wall->setDrawCallback(new DrawOnEvenFrames);
        addBase(*b.group, base);
        return sceneOf(b.group);
    });

    add(p, "draw_callback_draws_box_over_wall", "a draw callback draws a box behind the wall with GL's depth test off",
        [](const Build& b) {
            const Base base = makeBase();
            osg::Drawable* box = base.hidden[4]->getDrawable(0);
            box->setUseDisplayList(false);
            box->setDrawCallback(new DrawOverEverything);
            addBase(*b.group, base);
            return sceneOf(b.group);
        });
}

// ---------------------------------------------------------------------------------------------------
// Nodes placed at cull time, cameras in and beside the graph, structure.

void placementAndCameraPatterns(Patterns& p)
{
    add(p, "billboard_wall", "the wall an osg::Billboard quad (axial rotation about z) facing the eye",
        [](const Build& b) {
            osg::ref_ptr<osg::Billboard> billboard = new osg::Billboard;
            billboard->setMode(osg::Billboard::AXIAL_ROT);
            billboard->setAxis(Vec3(0, 0, 1));
            billboard->setNormal(Vec3(0, -1, 0));
            billboard->addDrawable(makeQuad(Vec3(-8, 0, -6), Vec3(8, 0, -6), Vec3(8, 0, 6), Vec3(-8, 0, 6), WallColour),
                                   Vec3(0, 20, 0));
            b.group->addChild(billboard);
            addBase(*b.group, makeBase(), Wall::None);
            return sceneOf(b.group);
        });

    add(p, "autotransform_rotate_to_screen", "the wall a quad under an AutoTransform ROTATE_TO_SCREEN",
        [](const Build& b) {
            osg::ref_ptr<osg::AutoTransform> autoTransform = new osg::AutoTransform;
            autoTransform->setAutoRotateMode(osg::AutoTransform::ROTATE_TO_SCREEN);
            autoTransform->setPosition(Vec3(0, 20, 0));
            autoTransform->addChild(
                geodeOf(makeQuad(Vec3(-8, -6, 0), Vec3(8, -6, 0), Vec3(8, 6, 0), Vec3(-8, 6, 0), WallColour)));
            b.group->addChild(autoTransform);
            addBase(*b.group, makeBase(), Wall::None);
            return sceneOf(b.group);
        });

    add(p, "autotransform_auto_scale_to_screen",
        "the only occluder a box ±20 units under an AutoTransform scaling it to the screen (40 pixels wide)",
        [](const Build& b) {
            osg::ref_ptr<osg::AutoTransform> autoTransform = new osg::AutoTransform;
            autoTransform->setAutoScaleToScreen(true);
            autoTransform->setPosition(Vec3(0, 20, 0));
            autoTransform->addChild(boxAt(Vec3(), 20.f, WallColour));
            b.group->addChild(autoTransform);
            addBase(*b.group, makeBase(), Wall::None);
            return sceneOf(b.group);
        });

    add(p, "absolute_reference_frame_plate",
        "an ABSOLUTE_RF MatrixTransform holding a plate 10 m before the eye (the only occluder) and a box, in eye "
        "coordinates",
        [](const Build& b) {
            osg::ref_ptr<osg::MatrixTransform> eyeFixed = new osg::MatrixTransform;
            eyeFixed->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
            eyeFixed->addChild(geodeOf(makeBox(Vec3(-2.5f, -1.8f, -10.5f), Vec3(2.5f, 1.8f, -10.f), WallColour)));
            eyeFixed->addChild(boxAt(Vec3(6, -3, -15), 0.8f, Vec4(1, 0.5f, 0, 1)));
            b.group->addChild(eyeFixed);
            addBase(*b.group, makeBase(), Wall::None);
            return sceneOf(b.group);
        });

    add(p, "hud_projection_node", "an osg::Projection + ABSOLUTE_RF HUD quad over the middle of the view (bin 11, no depth)",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Geometry> panel =
                makeQuad(Vec3(40, 30, 0), Vec3(88, 30, 0), Vec3(88, 66, 0), Vec3(40, 66, 0), Vec4(0.2f, 0.8f, 0.4f, 1));
            osg::StateSet* state = panel->getOrCreateStateSet();
            state->setMode(GL_DEPTH_TEST, osg::StateAttribute::OFF);
            state->setRenderBinDetails(11, "RenderBin");
            osg::ref_ptr<osg::MatrixTransform> absolute = new osg::MatrixTransform;
            absolute->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
            absolute->addChild(geodeOf(panel));
            osg::ref_ptr<osg::Projection> projection = new osg::Projection(osg::Matrix::ortho2D(0, Width, 0, Height));
            projection->addChild(absolute);
            b.group->addChild(projection);
            return sceneOf(b.group);
        });

    add(p, "hud_camera_post_render", "a nested POST_RENDER ABSOLUTE_RF camera (depth cleared) drawing a HUD quad",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Camera> hud = new osg::Camera;
            hud->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
            hud->setProjectionMatrixAsOrtho2D(0, Width, 0, Height);
            hud->setViewMatrix(osg::Matrix::identity());
            hud->setClearMask(GL_DEPTH_BUFFER_BIT);
            hud->setRenderOrder(osg::Camera::POST_RENDER);
            hud->setAllowEventFocus(false);
            hud->addChild(
                geodeOf(makeQuad(Vec3(30, 20, 0), Vec3(70, 20, 0), Vec3(70, 50, 0), Vec3(30, 50, 0), Vec4(0.9f, 0.9f, 0.2f, 1))));
            b.group->addChild(hud);
            return sceneOf(b.group);
        });

    add(p, "post_render_camera_depth_cleared",
        "a nested POST_RENDER camera (RELATIVE_RF: the main view and projection; only depth cleared) drawing a box "
        "that stands behind the wall",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Camera> overlay = new osg::Camera;
            overlay->setRenderOrder(osg::Camera::POST_RENDER);
            overlay->setClearMask(GL_DEPTH_BUFFER_BIT);
            overlay->setAllowEventFocus(false);
            overlay->addChild(boxAt(Vec3(-2, 45, -1), 1.5f, Vec4(1, 0.5f, 0, 1)));
            b.group->addChild(overlay);
            return sceneOf(b.group);
        });

    add(p, "rtt_camera_in_graph_other_cull_mask",
        "a PRE_RENDER render-to-texture camera in the graph (shadow-style, ABSOLUTE_RF, its own cull mask 0x1 that "
        "leaves the wall (0x2) out) over the same group; the main view shows its texture on a quad",
        [](const Build& b) {
            const Base base = makeBase();
            base.wallTransform->setNodeMask(0x2);
            addBase(*b.group, base);
            osg::ref_ptr<osg::Texture2D> texture = renderTexture();
            osg::ref_ptr<osg::Camera> rtt = new osg::Camera;
            renderToTexture(*rtt, texture);
            rtt->setReferenceFrame(osg::Transform::ABSOLUTE_RF);
            rtt->setProjectionMatrixAsPerspective(25.0, Aspect, 1.0, 200.0);
            rtt->setViewMatrixAsLookAt(osg::Vec3d(6, -10, 8), osg::Vec3d(0, 40, 0), osg::Vec3d(0, 0, 1));
            rtt->setInheritanceMask(osg::CullSettings::ALL_VARIABLES & ~osg::CullSettings::CULL_MASK);
            rtt->setCullMask(0x1);
            rtt->addChild(b.group);
            osg::ref_ptr<osg::Group> root = new osg::Group;
            root->addChild(rtt);
            root->addChild(b.group);
            root->addChild(screenShowing(texture));
            return sceneOf(root);
        });

    add(p, "rtt_slave_camera",
        "an RTT slave camera (viewer.addSlave, the master's scene, its eye 20 m to the right turned 25° left: it sees "
        "the grid past the wall's edge) whose texture the main view shows on a quad (node mask 0x4, left out of the "
        "slave's cull mask)",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Texture2D> texture = renderTexture();
            osg::ref_ptr<osg::Group> root = new osg::Group;
            root->addChild(b.group);
            root->addChild(screenShowing(texture));
            Scene scene = sceneOf(root);
            scene.setUpViewer = [texture](osgViewer::Viewer& viewer) {
                osg::ref_ptr<osg::Camera> slave = new osg::Camera;
                slave->setGraphicsContext(cameraOf(viewer).getGraphicsContext());
                renderToTexture(*slave, texture);
                slave->setCullMask(~0x4u);
                slave->setComputeNearFarMode(osg::CullSettings::DO_NOT_COMPUTE_NEAR_FAR);
                slave->setCullingMode(osg::CullSettings::VIEW_FRUSTUM_SIDES_CULLING);
                viewer.addSlave(slave, osg::Matrixd(),
                                osg::Matrixd::translate(-20, 0, 0) *
                                    osg::Matrixd::rotate(osg::DegreesToRadians(-25.0), osg::Vec3d(0, 1, 0)),
                                true);
            };
            return scene;
        });

    add(p, "nested_visibility_group", "a VisibilityGroup inside the group holding the boxes (a plain one for OSG)",
        [](const Build& b) {
            const Base base = makeBase();
            b.group->addChild(base.wallTransform);
            osg::ref_ptr<osg::Group> inner = b.makeInnerGroup();
            for (const auto& box : base.boxes)
                inner->addChild(box);
            b.group->addChild(inner);
            b.group->addChild(boxAt(Vec3(-2, 50, -3), 1.f, Vec4(1, 0.5f, 0, 1)));
            return sceneOf(b.group);
        });

    add(p, "eye_following_box_in_view", "the eye-following transform holds a small box 12 m ahead of the eye's origin",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<FollowTheEye> follow = new FollowTheEye;
            follow->setCullingActive(false);
            follow->addChild(boxAt(Vec3(2, 12, -1), 0.7f, Vec4(1, 0.5f, 0, 1)));
            b.group->addChild(follow);
            return sceneOf(b.group);
        });

    add(p, "osg_occluder_node", "OSG's own OccluderNode (a ConvexPlanarOccluder over the wall), shadow occlusion culling on",
        [](const Build& b) {
            const Base base = makeBase();
            osg::ref_ptr<osg::ConvexPlanarOccluder> occluder = new osg::ConvexPlanarOccluder;
            occluder->getOccluder().add(Vec3(-8, 20, -6));
            occluder->getOccluder().add(Vec3(8, 20, -6));
            occluder->getOccluder().add(Vec3(8, 20, 6));
            occluder->getOccluder().add(Vec3(-8, 20, 6));
            osg::ref_ptr<osg::OccluderNode> node = new osg::OccluderNode;
            node->setOccluder(occluder);
            node->addChild(base.wallTransform);
            b.group->addChild(node);
            addBase(*b.group, base, Wall::None);
            return sceneOf(b.group);
        });

    add(p, "cluster_culling_callbacks", "ClusterCullingCallbacks on the boxes (half face away from the eye)",
        [](const Build& b) {
            const Base base = makeBase();
            for (unsigned i = 0; i < base.boxes.size(); ++i)
            {
                osg::Drawable* box = base.boxes[i]->getDrawable(0);
                box->setCullCallback(new osg::ClusterCullingCallback(box->getBound().center(),
                                                                     Vec3(0, i % 2 ? 1.f : -1.f, 0), 0.f));
            }
            addBase(*b.group, base);
            return sceneOf(b.group);
        });

    add(p, "shared_geode_two_paths", "one box geode under two transforms: one behind the wall, one moving in front of it",
        [](const Build& b) {
            addBase(*b.group, makeBase());
            osg::ref_ptr<osg::Geode> shared = boxAt(Vec3(), 1.f, Vec4(1, 0.5f, 0, 1));
            osg::ref_ptr<osg::MatrixTransform> hidden = new osg::MatrixTransform(osg::Matrixd::translate(0, 40, 2));
            osg::ref_ptr<osg::MatrixTransform> moving = new osg::MatrixTransform;
            hidden->addChild(shared);
            moving->addChild(shared);
            b.group->addChild(hidden);
            b.group->addChild(moving);
            Scene scene = sceneOf(b.group);
            scene.animate = [moving](unsigned f) {
                moving->setMatrix(osg::Matrixd::translate(3, 12.0 + 23.0 * (0.5 - 0.5 * std::cos(0.3 * f)), -4));
            };
            return scene;
        });

    add(p, "one_geode_many_drawables", "the wall and every box as drawables of one Geode", [](const Build& b) {
        const Base base = makeBase();
        osg::ref_ptr<osg::Geode> geode = new osg::Geode;
        geode->addDrawable(base.wall);
        for (const auto& box : base.boxes)
            geode->addDrawable(box->getDrawable(0));
        b.group->addChild(geode);
        return sceneOf(b.group);
    });

    add(p, "slit_between_wall_halves", "the wall in two halves with a slit 0.1 m wide (about half a pixel)",
        [](const Build& b) {
            b.group->addChild(geodeOf(makeBox(Vec3(-8, 20, -6), Vec3(-0.05f, 21, 6), WallColour)));
            b.group->addChild(geodeOf(makeBox(Vec3(0.05f, 20, -6), Vec3(8, 21, 6), Vec4(0.5f, 0.5f, 0.5f, 1))));
            addBase(*b.group, makeBase(), Wall::None);
            b.group->addChild(boxAt(Vec3(0, 60, 0), 3.f, Vec4(1, 1, 1, 1)));
            return sceneOf(b.group);
        });

    add(p, "wall_of_tiles", "the wall as four boxes that meet edge to edge", [](const Build& b) {
        unsigned shade = 0;
        for (float x : {-8.f, 0.f})
            for (float z : {-6.f, 0.f})
            {
                const float grey = 0.45f + 0.1f * float(shade++);
                b.group->addChild(geodeOf(makeBox(Vec3(x, 20, z), Vec3(x + 8, 21, z + 6), Vec4(grey, grey, grey, 1))));
            }
        addBase(*b.group, makeBase(), Wall::None);
        return sceneOf(b.group);
    });

    add(p, "boxes_at_frame_edges", "boxes straddling the four edges and a corner of the frame", [](const Build& b) {
        addBase(*b.group, makeBase());
        // At y = 30 the view reaches 16.5 m to the side and 12.4 m up and down.
        const Vec3 edges[] = {Vec3(16.5f, 30, 0), Vec3(-16.5f, 30, 0), Vec3(0, 30, 12.4f), Vec3(-3, 30, -12.4f),
                              Vec3(16.5f, 30, 12.4f)};
        unsigned colour = 5;
        for (const Vec3& at : edges)
            b.group->addChild(boxAt(at, 1.f, colourOf(colour++)));
        return sceneOf(b.group);
    });
}
} // namespace

void standardProjection(osg::Camera& camera)
{
    camera.setProjectionMatrixAsPerspective(45.0, Aspect, 1.0, 200.0);
}

void standardView(osgViewer::Viewer& viewer, unsigned frame)
{
    cameraOf(viewer).setViewMatrix(lookFrom(eyeAt(frame), yawAt(frame), pitchAt(frame)));
}

const std::vector<Pattern>& patterns()
{
    static const std::vector<Pattern> all = [] {
        Patterns p;
        cameraAndStatePatterns(p);
        statePatterns(p);
        changingGraphPatterns(p);
        placementAndCameraPatterns(p);
        return p;
    }();
    return all;
}
} // namespace osgVis::test::sameimage
