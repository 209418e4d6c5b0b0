// SPDX-License-Identifier: MIT
// osgdb_pvs: the `.pvs` file (docs/pvs-format.md) as an osgDB format.
//
// Reading x.pvs gives the model the file names, under an osgVis::VisibilityGroup named "x.pvs":
// - the .pvs reads and was baked for the model → modes "cellportal", its data held by the group
//   (VisibilityGroup::setBakedData, not a process-wide store: two groups of one model may hold
//   different bakes, and the data go with the group), description "osgVis:pvs-trusted"; a file of
//   view cells only (osgvispvs --method multifocal) → modes "multifocal", its cells held likewise;
// - the .pvs was baked for another model (its geometry fingerprint, or for a version 1 file its
//   fingerprint, differs) or holds neither kind of data → modes "frustum", a warning, description
//   "osgVis:pvs-untrusted: <reason>";
// - the .pvs is corrupt, truncated or of a newer version → the model saved beside it (x.osgb,
//   x.osgt, x.ive, x.osg) under "frustum" with a warning, or an error when there is none;
// - the model it names cannot be found or read → an error naming the model and the .pvs.
// Writing x.pvs bakes the node and saves it beside as x.osgb (option "model=<file>" names an
// existing model file instead, which must be the same model); a group read from a .pvs writes its
// model. Read and write keep no state, so pager threads may call them at once.
#include "../NodeReaderWriter.h"
#include "PvsModelFiles.h"
#include "PvsTrust.h"

#include <osgVis/ModelRepair>
#include <osgVis/SceneExtractor>
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/core/multifocal/MultifocalModule.h>
#include <osgVis/core/pvs/PvsFormat.h>
#include <osgVis/core/scene/SceneFingerprint.h>

#include <osg/Notify>
#include <osgDB/FileNameUtils>
#include <osgDB/FileUtils>
#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgDB/WriteFile>

#include <iterator>
#include <memory>
#include <sstream>

namespace osgVis::pvsplugin
{
namespace
{
// The value of `key=<value>` among the whitespace-separated words of the options string, or "".
std::string optionValue(const osgDB::Options* options, const std::string& key)
{
    if (!options)
        return "";
    std::istringstream words(options->getOptionString());
    std::string word;
    while (words >> word)
        if (word.rfind(key + "=", 0) == 0)
            return word.substr(key.size() + 1);
    return "";
}

osgDB::ReaderWriter::ReadResult showCorruptWithModelBeside(const std::string& pvsFile, const std::string& reason,
                                                           const osgDB::Options* options)
{
    const std::string modelFile = findModelBeside(pvsFile);
    if (modelFile.empty())
        return osgDB::ReaderWriter::ReadResult("osgVis: " + pvsFile + " is corrupt (" + reason +
                                               ") and no model lies beside it (" +
                                               osgDB::getNameLessExtension(pvsFile) + ".osgb, .osgt, .ive or .osg)");
    osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(modelFile, options);
    if (!model)
        return osgDB::ReaderWriter::ReadResult("osgVis: " + pvsFile + " is corrupt (" + reason +
                                               ") and the model beside it, " + modelFile + ", cannot be read");
    repairLoadedModel(*model, modelFile);
    OSG_WARN << "osgVis: " << pvsFile << " is corrupt (" << reason << "); showing " << modelFile
             << " with frustum culling only" << std::endl;
    return makeUntrustedGroup(*model, osgDB::getSimpleFileName(pvsFile), "corrupt .pvs: " + reason);
}

osgDB::ReaderWriter::ReadResult showWithModel(core::PvsFile&& pvs, const std::string& pvsFile,
                                              const osgDB::Options* options)
{
    const std::string modelFile = findNamedModel(pvs.modelPath, pvsFile, options);
    if (modelFile.empty())
        return osgDB::ReaderWriter::ReadResult("osgVis: cannot find model '" + pvs.modelPath + "' named by " + pvsFile +
                                               " (looked beside the .pvs, as given and on the data path)");
    // A .pvs naming a .pvs (itself, say) would recurse without end.
    if (osgDB::getLowerCaseFileExtension(modelFile) == "pvs")
        return osgDB::ReaderWriter::ReadResult("osgVis: " + pvsFile + " names another .pvs, '" + modelFile +
                                               "', as its model");
    osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(modelFile, options);
    if (!model)
        return osgDB::ReaderWriter::ReadResult("osgVis: cannot read model '" + modelFile + "' named by " + pvsFile);
    repairLoadedModel(*model, modelFile); // as osgvispvs did before baking
    const std::string name = osgDB::getSimpleFileName(pvsFile);
    if (!pvs.hasCellPortal && !pvs.hasViewCells)
    {
        const std::string reason = "holds neither cell-portal data nor view cells (method '" + pvs.method + "')";
        OSG_WARN << "osgVis: " << pvsFile << " " << reason << "; showing " << modelFile << " with frustum culling only"
                 << std::endl;
        return makeUntrustedGroup(*model, name, reason);
    }
    if (pvs.sourceRange)
    {
        const std::string reason = "holds only source cells " + std::to_string(pvs.sourceRange->first) + "-" +
                                   std::to_string(pvs.sourceRange->second - 1) + " of " +
                                   std::to_string(pvs.data.sources.size()) +
                                   " (a range file of a split bake: join the ranges with osgvispvs merge)";
        OSG_WARN << "osgVis: " << pvsFile << " " << reason << "; showing " << modelFile << " with frustum culling only"
                 << std::endl;
        return makeUntrustedGroup(*model, name, reason);
    }
    const std::string mismatch = mismatchWithModel(pvs, *model);
    if (!mismatch.empty())
    {
        OSG_WARN << "osgVis: " << pvsFile << " was " << mismatch << ", not for " << modelFile
                 << "; showing the model with frustum culling only. Bake it again with osgvispvs." << std::endl;
        return makeUntrustedGroup(*model, name, mismatch);
    }
    auto baked = std::make_shared<core::BakedData>();
    if (pvs.hasViewCells)
    {
        auto cells = std::make_shared<core::BakedViewCells>();
        cells->fingerprint = pvs.data.fingerprint;
        cells->objectCount = pvs.data.objectCount;
        cells->nearDistance = pvs.nearDistance;
        cells->cells = std::move(pvs.viewCells);
        baked->set<core::BakedViewCells>(std::move(cells));
    }
    if (!pvs.hasCellPortal)
        return makeTrustedGroup(*model, name, std::move(baked), "multifocal");
    baked->set(std::make_shared<const core::CellPortalData>(std::move(pvs.data)));
    return makeTrustedGroup(*model, name, std::move(baked));
}
} // namespace

class ReaderWriterPvs : public plugins::NodeReaderWriter
{
public:
    ReaderWriterPvs() { supportsExtension("pvs", "osgVis cell-and-portal visibility (model + baked PVS)"); }
    const char* className() const override { return "osgVis .pvs reader/writer"; }

    using NodeReaderWriter::readNode;
    // A stream has no folder: the model it names is looked up relative to the options' database path.
    ReadResult readNode(std::istream& in, const Options* options) const override
    {
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::string folder =
            options && !options->getDatabasePathList().empty() ? options->getDatabasePathList().front() : ".";
        const std::string pvsFile = osgDB::concatPaths(folder, "<stream>.pvs");
        try
        {
            return showWithModel(core::decodePvs(bytes.data(), bytes.size()), pvsFile, options);
        }
        catch (const std::exception& e)
        {
            return ReadResult(std::string("osgVis: cannot read .pvs stream: ") + e.what());
        }
    }

    WriteResult writeObject(const osg::Object& object, const std::string& file, const Options* options) const override
    {
        const auto* node = dynamic_cast<const osg::Node*>(&object);
        return node ? writeNode(*node, file, options) : WriteResult(WriteResult::FILE_NOT_HANDLED);
    }

    WriteResult writeNode(const osg::Node& node, const std::string& file, const Options* options) const override
    {
        if (!acceptsExtension(osgDB::getLowerCaseFileExtension(file)))
            return WriteResult::FILE_NOT_HANDLED;
        // note: extraction only reads the graph; osgVis::extractScene takes a non-const root.
        osg::Node& subject = const_cast<osg::Node&>(isPvsGroup(node) ? *node.asGroup()->getChild(0) : node);
        try
        {
            const osg::ref_ptr<ExtractedScene> extracted = extractScene(subject);
            const core::Scene& scene = extracted->scene;
            if (scene.objects.empty())
                return WriteResult("osgVis: nothing to bake for " + file + ": the node holds no drawable objects");

            std::string modelFile = optionValue(options, "model");
            if (!modelFile.empty())
            {
                const std::string besidePvs = osgDB::concatPaths(osgDB::getFilePath(file), modelFile);
                if (!osgDB::fileExists(modelFile) && osgDB::fileExists(besidePvs))
                    modelFile = besidePvs;
                osg::ref_ptr<osg::Node> model = osgDB::readRefNodeFile(modelFile);
                if (!model)
                    return WriteResult("osgVis: cannot read model=" + modelFile + " for " + file);
                const osg::ref_ptr<ExtractedScene> named = extractScene(*model);
                if (core::sceneGeometryFingerprint(named->scene) != core::sceneGeometryFingerprint(scene))
                    return WriteResult("osgVis: model=" + modelFile + " is not the node being written to " + file +
                                       " (their fingerprints differ)");
            }

            core::PvsFile pvs;
            const core::BakeOptions bake;
            pvs.data = core::bakeCellPortal(scene, bake);
            pvs.method = "cellportal";
            pvs.options = core::canonicalBakeOptions(bake);
            pvs.geometryFingerprint = core::sceneGeometryFingerprint(scene);
            if (modelFile.empty())
            {
                modelFile = osgDB::getNameLessExtension(file) + ".osgb";
                if (!osgDB::writeNodeFile(subject, modelFile))
                    return WriteResult("osgVis: cannot write the model of " + file + " to " + modelFile);
            }
            pvs.modelPath = modelPathFromPvs(modelFile, file);
            core::writePvsFile(file, pvs);
            return WriteResult::FILE_SAVED;
        }
        catch (const std::exception& e)
        {
            return WriteResult("osgVis: cannot write " + file + ": " + e.what());
        }
    }

    WriteResult writeNode(const osg::Node&, std::ostream&, const Options*) const override
    {
        return WriteResult("osgVis: a .pvs is written to a file, with its model beside it, not to a stream");
    }

protected:
    ReadResult readFound(const std::string&, const std::string& pvsFile, const Options* options) const override
    {
        try
        {
            core::PvsFile pvs;
            try
            {
                pvs = core::readPvsFile(pvsFile);
            }
            catch (const core::PvsFormatError& e)
            {
                // The messages below name the file already; keep the reason only.
                std::string reason = e.what();
                if (reason.rfind(pvsFile + ": ", 0) == 0)
                    reason.erase(0, pvsFile.size() + 2);
                return showCorruptWithModelBeside(pvsFile, reason, options);
            }
            return showWithModel(std::move(pvs), pvsFile, options);
        }
        catch (const std::exception& e) // e.g. no "cellportal" module registered
        {
            return ReadResult("osgVis: cannot show " + pvsFile + ": " + e.what());
        }
    }
};
} // namespace osgVis::pvsplugin

// note: the macro pastes the class name into identifiers, so it takes an unqualified name.
using osgVis::pvsplugin::ReaderWriterPvs;
REGISTER_OSGPLUGIN(pvs, ReaderWriterPvs)
