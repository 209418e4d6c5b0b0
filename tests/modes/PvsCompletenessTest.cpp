// SPDX-License-Identifier: MIT
// The cell-portal contract at the level of its parts: from eyes sampled inside every cell, looking
// in all six cube directions, every object the oracle's ID render sees lies in that cell's PVS
// (cell-to-object) and in the module's eye-to-object answer for that view. Scenes: a small office
// and the multi-storey office (floors, ceilings and stairs of walls), plus slanted walls.
#include <osgVis/SceneExtractor>
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/gen/Generator.h>
#include <osgVis/oracle/IdBufferOracle.h>

#include "AppProcess.h"

#include <gtest/gtest.h>

#include <osg/Matrixd>

#include <glm/gtc/type_ptr.hpp>

#include <random>
#include <sstream>

namespace
{
using namespace osgVis;

struct CubeFace
{
    osg::Vec3d forward, up;
};
const CubeFace cubeFaces[6] = {{{1, 0, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}},
                               {{0, -1, 0}, {0, 0, 1}}, {{0, 0, 1}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}}};

core::Vec3 pointInside(const core::Aabb& cell, std::mt19937& random)
{
    // Anywhere in the cell, its boundary included (eyes on portals and walls are the hard cases).
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    core::Vec3 p;
    for (int axis = 0; axis < 3; ++axis)
    {
        const double t = unit(random);
        p[axis] = cell.min[axis] + (t < 0.1 ? 0.0 : t > 0.9 ? 1.0 : t) * (cell.max[axis] - cell.min[axis]);
    }
    return p;
}

bool inSomePvs(const core::CellPortalData& data, const std::vector<std::uint32_t>& cells, core::ObjectId id)
{
    for (std::uint32_t cell : cells)
        if (data.sources[cell].cellToObject.test(id))
            return true;
    return false;
}

struct Failure
{
    std::size_t count = 0;
    std::ostringstream first;
};

void checkScene(osg::Node& model, unsigned eyesPerCell, std::size_t maxCells)
{
    const osg::ref_ptr<ExtractedScene> extracted = extractScene(model);
    const core::Scene& scene = extracted->scene;
    core::CellPortalModule module(core::CellPortalStage::EyeToObject);
    module.setScene(scene);
    const core::CellPortalData& data = *module.bakedData();
    ASSERT_GT(data.graph.cells.size(), 1u);

    oracle::OracleSettings settings;
    settings.width = 96;
    settings.height = 96;
    settings.supersample = 2;
    oracle::IdBufferOracle idBuffer(&model, settings);
    std::vector<core::ObjectId> sceneIdOf;
    for (const oracle::OracleObject& object : idBuffer.objects())
        sceneIdOf.push_back(extracted->find(object.drawable.get(), object.path));

    const double diagonal = glm::length(scene.bounds().extent());
    const double nearPlane = 0.01, farPlane = 2.0 * diagonal + 10.0;
    const osg::Matrixd projection = osg::Matrixd::perspective(90.0, 1.0, nearPlane, farPlane);
    std::mt19937 random(7);
    const std::size_t step = std::max<std::size_t>(1, data.graph.cells.size() / maxCells);
    Failure pvsMisses, moduleMisses;
    std::size_t views = 0, seen = 0;
    for (std::size_t cell = 0; cell < data.graph.cells.size(); cell += step)
        for (unsigned e = 0; e < eyesPerCell; ++e)
        {
            const core::Vec3 eye = pointInside(data.graph.cells[cell], random);
            // The eye's cells: those within the near plane's reach (geometry nearer is clipped, so
            // the eye sees through a wall it stands on).
            std::vector<std::uint32_t> eyeCells;
            data.graph.locate(eye, nearPlane * std::sqrt(3.0), eyeCells);
            for (const CubeFace& face : cubeFaces)
            {
                const osg::Vec3d from(eye.x, eye.y, eye.z);
                const osg::Matrixd view = osg::Matrixd::lookAt(from, from + face.forward, face.up);
                const oracle::IdBufferOracle::Result result = idBuffer.visible(view, projection);
                core::VisibleSet answer(scene.objects.size(), true);
                const core::Mat4 viewMatrix = glm::make_mat4(view.ptr());
                const core::Mat4 projectionMatrix = glm::make_mat4(projection.ptr());
                module.cull(core::makeView(viewMatrix, projectionMatrix, 0.0, settings.width, settings.height), answer);
                ++views;
                for (std::uint32_t oracleIndex : result.visible)
                {
                    const core::ObjectId id = sceneIdOf[oracleIndex];
                    ASSERT_NE(id, core::InvalidObject);
                    ++seen;
                    if (!inSomePvs(data, eyeCells, id) && pvsMisses.count++ == 0)
                        pvsMisses.first << "object " << id << " (" << scene.objects[id].name << ") seen from "
                                        << eye.x << "," << eye.y << "," << eye.z << " in cell " << cell
                                        << " is not in the PVS of any cell within the near plane's reach";
                    if (!answer.test(id) && moduleMisses.count++ == 0)
                        moduleMisses.first << "object " << id << " (" << scene.objects[id].name << ") seen from "
                                           << eye.x << "," << eye.y << "," << eye.z << " looking " << face.forward.x()
                                           << "," << face.forward.y() << "," << face.forward.z()
                                           << " is missing from the eye-to-object answer";
                }
            }
        }
    std::cout << data.graph.cells.size() << " cells, " << views << " views, " << seen << " objects seen" << std::endl;
    EXPECT_EQ(pvsMisses.count, 0u) << pvsMisses.first.str();
    EXPECT_EQ(moduleMisses.count, 0u) << moduleMisses.first.str();
    EXPECT_GT(seen, views / 2); // the renders saw something: the check is not vacuous
}

class PvsCompleteness : public ::testing::Test
{
protected:
    void SetUp() override
    {
        if (!test::haveDisplay())
            GTEST_SKIP() << "needs a display (scripts/test.sh runs the tests under Xvfb)";
    }
};

TEST_F(PvsCompleteness, OfficeEveryObjectSeenFromACellIsInItsPvs)
{
    gen::GenerateOptions options;
    options.kind = gen::SceneKind::Office;
    options.triangles = 20000;
    const gen::GeneratedScene generated = gen::generate(options);
    checkScene(*generated.root, 2, 400);
}

TEST_F(PvsCompleteness, ThinSlitSceneKeepsWhatShowsThroughTheSlit)
{
    const gen::GeneratedScene generated = gen::adversarialScene("thin-slit");
    checkScene(*generated.root, 6, 400);
}
} // namespace
