// SPDX-License-Identifier: MIT
#include <osgVis/core/api/ModuleSettings.h>

#include <osgVis/core/api/ModuleRegistry.h>
#include <osgVis/core/frustum/FrustumModule.h>

#include "ModeText.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <type_traits>

namespace osgVis::core
{
namespace
{
// One setting of a module: its key and its value as text, read and written.
template <class Options> struct Key
{
    const char* name;
    std::function<std::string(const Options&)> write;
    std::function<bool(Options&, const std::string&)> read; ///< false: not a value of this key
};

std::string valueText(bool value)
{
    return value ? "true" : "false";
}

// The shortest text that reads back to the same double.
std::string valueText(double value)
{
    char text[32];
    for (int precision = 1; precision <= 17; ++precision)
    {
        std::snprintf(text, sizeof(text), "%.*g", precision, value);
        if (std::strtod(text, nullptr) == value)
            break;
    }
    return text;
}

template <class Unsigned, class = std::enable_if_t<std::is_unsigned_v<Unsigned>>> std::string valueText(Unsigned value)
{
    return std::to_string(value);
}

bool readValue(const std::string& text, bool& value)
{
    if (text != "true" && text != "false")
        return false;
    value = text == "true";
    return true;
}

bool readValue(const std::string& text, double& value)
{
    char* end = nullptr;
    const double read = text.empty() ? 0.0 : std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(read))
        return false;
    value = read;
    return true;
}

template <class Unsigned, class = std::enable_if_t<std::is_unsigned_v<Unsigned>>>
bool readValue(const std::string& text, Unsigned& value)
{
    if (text.empty() || text.size() > 19 || text.find_first_not_of("0123456789") != std::string::npos)
        return false;
    const unsigned long long read = std::strtoull(text.c_str(), nullptr, 10);
    if (read > std::numeric_limits<Unsigned>::max())
        return false;
    value = Unsigned(read);
    return true;
}

template <class Options, class T> Key<Options> field(const char* name, T Options::*member)
{
    return {name, [member](const Options& options) { return valueText(options.*member); },
            [member](Options& options, const std::string& text) { return readValue(text, options.*member); }};
}

template <class Options, class Enum>
Key<Options> choice(const char* name, Enum Options::*member, std::vector<std::pair<const char*, Enum>> names)
{
    return {name,
            [member, names](const Options& options)
            {
                for (const auto& [text, value] : names)
                    if (options.*member == value)
                        return std::string(text);
                return std::string("?");
            },
            [member, names](Options& options, const std::string& text)
            {
                for (const auto& [known, value] : names)
                    if (text == known)
                        return options.*member = value, true;
                return false;
            }};
}

// The keys of each module's options. None for the cell-portal stages (the stage is the name) and
// the mask's shrinkage rule (approximate or not: the name says).
template <class Options> const std::vector<Key<Options>>& keysOf()
{
    static const std::vector<Key<Options>> none;
    return none;
}

template <> const std::vector<Key<OctreeOptions>>& keysOf()
{
    using O = OctreeOptions;
    static const std::vector<Key<O>> keys = {
        field("occluders", &O::occluders),
        field("areaAngleThreshold", &O::areaAngleThreshold),
        field("fuseConnected", &O::fuseConnected),
        field("fuseDisjoint", &O::fuseDisjoint),
        field("temporalCoherence", &O::temporalCoherence),
        field("coplanarUnions", &O::coplanarUnions),
        field("sweepAreaAngleThreshold", &O::sweepAreaAngleThreshold),
        field("occlusionTreeMaxNodes", &O::occlusionTreeMaxNodes),
        field("maxLeafObjects", &O::maxLeafObjects),
        field("parallelMinObjects", &O::parallelMinObjects),
        field("sceneHierarchy", &O::sceneHierarchy),
        field("workBudget", &O::workBudget),
    };
    return keys;
}

template <> const std::vector<Key<MaskOptions>>& keysOf()
{
    using O = MaskOptions;
    static const std::vector<Key<O>> keys = {
        choice("measure", &O::measure,
               {{"coverage", OccluderMeasure::CoverageImportance}, {"distance", OccluderMeasure::Distance}}),
        field("shrinkPixels", &O::shrinkPixels),
        field("maskDownscale", &O::maskDownscale),
        field("occluders", &O::occluders),
        field("maxOccluderPolygons", &O::maxOccluderPolygons),
        field("minOccluderDistance", &O::minOccluderDistance),
        field("maxEyeSpeed", &O::maxEyeSpeed),
        field("stopObjects", &O::stopObjects),
        field("maxLeafObjects", &O::maxLeafObjects),
        field("sceneHierarchy", &O::sceneHierarchy),
        field("workBudget", &O::workBudget),
        field("boxTestWork", &O::boxTestWork),
    };
    return keys;
}

template <> const std::vector<Key<CdtOptions>>& keysOf()
{
    using O = CdtOptions;
    using Rule = CdtOptions::Rule;
    static const std::vector<Key<O>> keys = {
        choice("rule", &O::rule,
               {{"combined", Rule::Combined}, {"depthfree", Rule::DepthFree}, {"depth", Rule::DepthOnly}}),
        field("constraintBudget", &O::constraintBudget),
        field("testBudget", &O::testBudget),
        field("tolerancePixels", &O::tolerancePixels),
        field("maxLeafObjects", &O::maxLeafObjects),
        field("sceneHierarchy", &O::sceneHierarchy),
    };
    return keys;
}

template <> const std::vector<Key<MultifocalModuleOptions>>& keysOf()
{
    using O = MultifocalModuleOptions;
    static const std::vector<Key<O>> keys = {field("cachedCells", &O::cachedCells)};
    return keys;
}

// Whether two options agree on what only a name says.
template <class Options> bool sameNamedPart(const Options&, const Options&)
{
    return true;
}
bool sameNamedPart(const MaskOptions& a, const MaskOptions& b)
{
    return a.shrink == b.shrink;
}
bool sameNamedPart(const CellPortalStage& a, const CellPortalStage& b)
{
    return a == b;
}

template <class Options> void readKey(Options& options, const std::string& stage, const std::string& setting)
{
    const std::size_t equals = setting.find('=');
    const std::string key = setting.substr(0, equals);
    const std::vector<Key<Options>>& keys = keysOf<Options>();
    std::vector<std::string> names;
    for (const Key<Options>& known : keys)
    {
        names.push_back(known.name);
        if (key != known.name)
            continue;
        if (equals == std::string::npos || !known.read(options, setting.substr(equals + 1)))
            throw UnknownModeError("mode '" + stage + "': bad value in '" + setting + "' (e.g. " + key + "=" +
                                   known.write(options) + ")");
        return;
    }
    if (keys.empty())
        throw UnknownModeError("mode '" + stage + "': this module takes no settings");
    throw UnknownModeError("mode '" + stage + "': no setting '" + key + "' (settings: " + modetext::joined(names) + ")");
}

StageSettings stage(const char* name, decltype(StageSettings::options) options = {})
{
    return StageSettings{name, std::move(options)};
}

} // namespace

const std::vector<StageSettings>& builtInStages()
{
    static const std::vector<StageSettings> stages = []
    {
        OctreeOptions single, paper;
        single.fuseConnected = false;
        single.fuseDisjoint = false;
        paper.fuseDisjoint = false;
        MaskOptions approx, distance;
        approx.shrink = MaskShrink::FusedUnion;
        approx.shrinkPixels = 4.0; // the paper's variant at the shrinkage its figures use
        distance.measure = OccluderMeasure::Distance;
        CdtOptions depthFree, depthOnly;
        depthFree.rule = CdtOptions::Rule::DepthFree;
        depthOnly.rule = CdtOptions::Rule::DepthOnly;
        return std::vector<StageSettings>{
            stage("frustum"),
            stage("octree", OctreeOptions()),
            stage("octree-single", single),
            stage("octree-paper", paper),
            stage("mask", MaskOptions()),
            stage("mask-approx", approx),
            stage("mask-distance", distance),
            stage("cdt", CdtOptions()),
            stage("cdt-depthfree", depthFree),
            stage("cdt-depth", depthOnly),
            stage("cellportal", CellPortalStage::EyeToObject),
            stage("cellportal-cells", CellPortalStage::CellToCell),
            stage("cellportal-pvs", CellPortalStage::CellToObject),
            stage("cellportal-eyecells", CellPortalStage::EyeToCell),
            stage("multifocal", MultifocalModuleOptions()),
        };
    }();
    return stages;
}

StageSettings parseStageSettings(const std::string& text)
{
    const std::vector<std::string> parts = modetext::split(text, ":");
    for (const StageSettings& known : builtInStages())
        if (known.name == parts[0])
        {
            StageSettings settings = known;
            for (std::size_t i = 1; i < parts.size(); ++i)
                std::visit([&](auto& options) { readKey(options, text, parts[i]); }, settings.options);
            return settings;
        }
    if (parts.size() > 1)
        throw UnknownModeError("mode '" + text + "': only osgVis's own modules take settings, and '" + parts[0] +
                               "' is none of them");
    return StageSettings{parts[0], {}};
}

ChainSettings parseChainSettings(const std::string& text)
{
    ChainSettings chain;
    for (const std::string& stage : modetext::split(text, ",+"))
        chain.push_back(parseStageSettings(stage));
    return chain;
}

std::string formatStageSettings(const StageSettings& settings)
{
    return std::visit(
        [&](const auto& options) -> std::string
        {
            using Options = std::decay_t<decltype(options)>;
            const StageSettings* nearest = nullptr;
            std::size_t fewest = std::numeric_limits<std::size_t>::max();
            for (const StageSettings& known : builtInStages())
            {
                const Options* base = std::get_if<Options>(&known.options);
                if (!base || !sameNamedPart(*base, options))
                    continue;
                std::size_t differing = 0;
                for (const Key<Options>& key : keysOf<Options>())
                    differing += key.write(*base) != key.write(options);
                if (differing < fewest)
                    nearest = &known, fewest = differing;
            }
            if (!nearest || std::is_same_v<Options, std::monostate>)
                return settings.name;
            std::string text = nearest->name;
            for (const Key<Options>& key : keysOf<Options>())
                if (key.write(std::get<Options>(nearest->options)) != key.write(options))
                    text += std::string(":") + key.name + "=" + key.write(options);
            return text;
        },
        settings.options);
}

std::string formatChainSettings(const ChainSettings& chain)
{
    std::string text;
    for (const StageSettings& stage : chain)
        text += (text.empty() ? "" : "+") + formatStageSettings(stage);
    return text;
}

std::vector<std::pair<std::string, std::string>> stageKeys(const StageSettings& settings)
{
    return std::visit(
        [](const auto& options)
        {
            std::vector<std::pair<std::string, std::string>> keys;
            for (const auto& key : keysOf<std::decay_t<decltype(options)>>())
                keys.emplace_back(key.name, key.write(options));
            return keys;
        },
        settings.options);
}

std::unique_ptr<VisibilityModule> createModule(const StageSettings& stage)
{
    struct Make
    {
        const std::string& name;
        std::unique_ptr<VisibilityModule> operator()(std::monostate) const
        {
            // note: frustum is made here, not by name: the registry makes its built-ins through this.
            if (name == "frustum")
                return std::make_unique<FrustumModule>();
            return createModule(name);
        }
        std::unique_ptr<VisibilityModule> operator()(const OctreeOptions& o) const { return std::make_unique<OctreeModule>(o); }
        std::unique_ptr<VisibilityModule> operator()(const MaskOptions& o) const { return std::make_unique<MaskModule>(o); }
        std::unique_ptr<VisibilityModule> operator()(const CdtOptions& o) const { return std::make_unique<CdtModule>(o); }
        std::unique_ptr<VisibilityModule> operator()(CellPortalStage s) const { return std::make_unique<CellPortalModule>(s); }
        std::unique_ptr<VisibilityModule> operator()(const MultifocalModuleOptions& o) const
        {
            return std::make_unique<MultifocalModule>(o);
        }
    };
    return std::visit(Make{stage.name}, stage.options);
}

ModuleChain createChain(const ChainSettings& chain)
{
    ModuleChain modules;
    for (const StageSettings& stage : chain)
        modules.add(createModule(stage));
    return modules;
}
} // namespace osgVis::core
