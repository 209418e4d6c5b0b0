#include "BenchOptions.h"

#include <cstdlib>
#include <sstream>

namespace osgVis::bench
{
namespace
{
std::string quotedArgument(const std::string& arg)
{
    if (!arg.empty() && arg.find_first_of(" \t\"'\\$") == std::string::npos)
        return arg;
    std::string quoted = "'";
    for (char c : arg)
        quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::uint64_t parseUnsigned(const std::string& flag, const std::string& text)
{
    // note: strtoull accepts a leading '-' and wraps it; reject it here so "--views -3" is an error.
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError(flag + " expects a non-negative integer, got '" + text + "'");
    return std::strtoull(text.c_str(), nullptr, 10);
}

std::vector<std::string> splitList(const std::string& text, char separator)
{
    std::vector<std::string> items;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, separator))
        items.push_back(item);
    if (!text.empty() && text.back() == separator)
        items.emplace_back();
    return items;
}

void parseSize(const std::string& text, unsigned& width, unsigned& height)
{
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos)
        throw UsageError("--size expects WxH (e.g. 640x480), got '" + text + "'");
    width = unsigned(parseUnsigned("--size", text.substr(0, x)));
    height = unsigned(parseUnsigned("--size", text.substr(x + 1)));
    if (width == 0 || height == 0 || width > 16384 || height > 16384)
        throw UsageError("--size must lie between 1x1 and 16384x16384, got '" + text + "'");
}
} // namespace

std::string benchUsage()
{
    return "usage: osgvisbench (--scene FILE | --generate office|city|tetra [--triangles N] [--seed S])\n"
           "                   [--walk FILE] [--modes osg,osg-oq,exact,frustum,frustum+octree,...]\n"
           "                   [--views N] [--size WxH] [--supersample K] [--json OUT.json] [--help]\n"
           "\n"
           "Renders every mode over the same walk in one process and measures it against the\n"
           "exact-visibility oracle (docs/benchmark.md). A module chain is written with '+'.\n"
           "Default modes: osg,frustum,exact. Exit status: 0 ok, 1 a conservative mode culled a\n"
           "visible object or the run failed, 2 bad command line.\n";
}

BenchOptions parseBenchOptions(int argc, char** argv)
{
    BenchOptions options;
    options.modes = {"osg", "frustum", "exact"};
    for (int i = 0; i < argc; ++i)
        options.commandLine += (i ? " " : "") + quotedArgument(argv[i]);

    for (int i = 1; i < argc; ++i)
    {
        const std::string flag = argv[i];
        auto value = [&]() -> std::string
        {
            if (i + 1 >= argc)
                throw UsageError(flag + " needs a value");
            return argv[++i];
        };
        if (flag == "--help" || flag == "-h")
            options.help = true;
        else if (flag == "--scene")
            options.sceneFile = value();
        else if (flag == "--generate")
            options.generateKind = value();
        else if (flag == "--triangles")
            options.triangles = parseUnsigned(flag, value());
        else if (flag == "--seed")
            options.seed = std::uint32_t(parseUnsigned(flag, value()));
        else if (flag == "--walk")
            options.walkFile = value();
        else if (flag == "--modes")
            options.modes = splitList(value(), ',');
        else if (flag == "--views")
            options.views = unsigned(parseUnsigned(flag, value()));
        else if (flag == "--size")
            parseSize(value(), options.width, options.height);
        else if (flag == "--json")
            options.jsonFile = value();
        else if (flag == "--supersample")
            options.supersample = unsigned(parseUnsigned(flag, value()));
        else
            throw UsageError("unknown argument '" + flag + "'");
    }
    if (options.help)
        return options;
    if (options.sceneFile.empty() == options.generateKind.empty())
        throw UsageError("give exactly one of --scene FILE or --generate KIND");
    if (options.modes.empty())
        throw UsageError("--modes is empty");
    for (const std::string& mode : options.modes)
        if (mode.empty())
            throw UsageError("--modes contains an empty name");
    if (options.supersample < 1 || options.supersample > 8)
        throw UsageError("--supersample must lie between 1 and 8");
    return options;
}
} // namespace osgVis::bench
