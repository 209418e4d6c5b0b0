#pragma once
// Command line of osgvisviewer: what to show (a model file or a generated scene), how to cull it,
// which walk to follow and whether to render it offscreen.
#include <cstdint>
#include <stdexcept>
#include <string>

namespace osgVis::viewer
{
struct OptionsError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

struct ViewerOptions
{
    std::string scenePath;     // any OSG-readable model; empty when generateKind is set
    std::string generateKind;  // "office", "city", "tetra" or empty
    std::uint64_t triangles = 200000; // size knob of --generate
    std::uint32_t seed = 1;           // seed of --generate
    std::string mode = "frustum";     // "osg" or a module chain such as "frustum+octree"
    std::string walkPath;             // empty: SCENE's stem + ".walk", else an automatic walk
    std::string recordPath;           // where `r` saves the recorded eye path
    std::string headlessDir;          // non-empty: render the walk offscreen into this folder
    unsigned width = 0, height = 0;   // pixels; 0 keeps the walk's own size
    std::string threading;            // --threading: an OSG threading model name; empty: OSG's choice
    bool async = false;               // --async on: asynchronous visibility for the module chains
    bool help = false;
};

// Parses argv; throws OptionsError naming the offending argument.
ViewerOptions parseOptions(int argc, char** argv);
std::string usageText(const std::string& programName);
} // namespace osgVis::viewer
