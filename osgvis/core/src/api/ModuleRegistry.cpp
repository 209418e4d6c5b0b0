// SPDX-License-Identifier: MIT
#include <osgVis/core/api/ModuleRegistry.h>

#include <osgVis/core/cdt/CdtModule.h>
#include <osgVis/core/cellportal/CellPortalModule.h>
#include <osgVis/core/frustum/FrustumModule.h>
#include <osgVis/core/mask/MaskModule.h>
#include <osgVis/core/multifocal/MultifocalModule.h>
#include <osgVis/core/octree/OctreeModule.h>
#include <osgVis/core/plugin/CallbackModule.h>
#include <osgVis/core/plugin/PluginModules.h>

#include <cstdlib>
#include <map>
#include <mutex>

namespace osgVis::core
{
namespace
{
struct Registry
{
    Registry()
    {
        factories["frustum"] = [] { return std::make_unique<FrustumModule>(); };
        factories["octree"] = [] { return std::make_unique<OctreeModule>(); };
        factories["octree-single"] = []
        {
            OctreeOptions single;
            single.fuseConnected = false;
            single.fuseDisjoint = false;
            return std::make_unique<OctreeModule>(single);
        };
        factories["octree-paper"] = []
        {
            OctreeOptions paper;
            paper.fuseDisjoint = false;
            return std::make_unique<OctreeModule>(paper);
        };
        const std::pair<const char*, CellPortalStage> cellPortalStages[] = {
            {"cellportal", CellPortalStage::EyeToObject},
            {"cellportal-cells", CellPortalStage::CellToCell},
            {"cellportal-pvs", CellPortalStage::CellToObject},
            {"cellportal-eyecells", CellPortalStage::EyeToCell},
        };
        for (const auto& [name, stage] : cellPortalStages)
            factories[name] = [stage = stage] { return std::make_unique<CellPortalModule>(stage); };
        factories["mask"] = [] { return std::make_unique<MaskModule>(); };
        factories["mask-approx"] = []
        {
            MaskOptions approx;
            approx.shrink = MaskShrink::FusedUnion;
            approx.shrinkPixels = 4.0; // the paper's variant at the shrinkage its figures use
            return std::make_unique<MaskModule>(approx);
        };
        factories["multifocal"] = [] { return std::make_unique<MultifocalModule>(); };
        for (const auto& [name, rule] : {std::pair{"cdt", CdtOptions::Rule::Combined},
                                          std::pair{"cdt-depthfree", CdtOptions::Rule::DepthFree},
                                          std::pair{"cdt-depth", CdtOptions::Rule::DepthOnly}})
        {
            CdtOptions options;
            options.rule = rule;
            factories[name] = [options]() mutable {
                // Like OSG's own OSG_* variables: a knob for measuring, e.g. the efficacy against
                // the constraint budget, without rebuilding (docs/cdt.md).
                if (const char* budget = std::getenv("OSGVIS_CDT_CONSTRAINT_BUDGET"))
                    options.constraintBudget = std::uint32_t(std::strtoul(budget, nullptr, 10));
                return std::make_unique<CdtModule>(options);
            };
        }
        factories["mask-distance"] = []
        {
            MaskOptions distance;
            distance.measure = OccluderMeasure::Distance;
            return std::make_unique<MaskModule>(distance);
        };
    }

    std::mutex mutex;
    std::map<std::string, ModuleFactory> factories;
};

// note: function-local static, so modules may register from static initializers of other
// libraries in any order.
Registry& registry()
{
    static Registry r;
    return r;
}

std::string joined(const std::vector<std::string>& names)
{
    std::string out;
    for (const std::string& n : names)
    {
        if (!out.empty())
            out += ", ";
        out += n;
    }
    return out;
}

std::string trimmed(const std::string& s)
{
    const char* space = " \t\r\n";
    const std::size_t first = s.find_first_not_of(space);
    if (first == std::string::npos)
        return {};
    const std::size_t last = s.find_last_not_of(space);
    return s.substr(first, last - first + 1);
}
} // namespace

std::vector<std::string> moduleNames()
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    std::vector<std::string> names;
    for (const auto& entry : r.factories)
        names.push_back(entry.first); // std::map keeps them sorted
    return names;
}

bool hasModule(const std::string& name)
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    return r.factories.count(name) != 0;
}

void registerModule(const std::string& name, ModuleFactory factory)
{
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    r.factories[name] = std::move(factory);
}

std::unique_ptr<VisibilityModule> createModule(const std::string& name)
{
    ModuleFactory factory;
    {
        Registry& r = registry();
        std::lock_guard<std::mutex> lock(r.mutex);
        const auto found = r.factories.find(name);
        if (found != r.factories.end())
            factory = found->second;
    }
    try
    {
        if (factory)
            return factory();
        if (std::unique_ptr<VisibilityModule> plugin = loadPluginModule(name))
            return plugin;
    }
    catch (const ModuleLoadFailure& e)
    {
        throw ModuleLoadError("mode '" + name + "': " + e.what());
    }
    throw UnknownModeError("unknown mode '" + name + "' (known: " + joined(moduleNames()) + "; no plugin " +
                           pluginFileName(name) + " in " + joined(pluginSearchPath()) + ")");
}

ModuleChain createChain(const std::string& names)
{
    ModuleChain chain;
    std::size_t start = 0;
    while (true)
    {
        const std::size_t comma = names.find_first_of(",+", start);
        const std::string name =
            trimmed(names.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (name.empty())
            throw UnknownModeError("empty mode name in '" + names + "' (known: " + joined(moduleNames()) + ")");
        chain.add(createModule(name));
        if (comma == std::string::npos)
            break;
        start = comma + 1;
    }
    return chain;
}
} // namespace osgVis::core
