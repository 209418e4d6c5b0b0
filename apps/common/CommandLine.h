// SPDX-License-Identifier: MIT
#pragma once
// One command-line parser for every osgVis app. An app declares its options with what each sets;
// parse() reads the arguments in order and fails the same way in every app (UsageError: the app
// prints it and exits 2). Our own, not CLI11 or cxxopts: the apps' help texts are written by hand
// in sections and their tests assert them, and what the apps need (flags, values, positional
// arguments, subcommands, checks of the options together done by the app) fits in a page; the
// value parsers below are where the apps' repeated code was.
#include <array>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace osgVis::apps
{
// A bad command line; its message names the offending argument.
struct UsageError : std::runtime_error
{
    using std::runtime_error::runtime_error;
};

class CommandLine
{
public:
    using ValueHandler = std::function<void(const std::string& value)>;

    // An option without a value: sets `target` (to true), or calls `handler`.
    CommandLine& flag(std::initializer_list<const char*> names, bool& target);
    CommandLine& flag(std::initializer_list<const char*> names, std::function<void()> handler);
    // An option taking the next argument as its value, whatever it looks like ("--eye -1,2,3").
    CommandLine& value(std::initializer_list<const char*> names, std::string& target);
    CommandLine& value(std::initializer_list<const char*> names, ValueHandler handler);
    // The arguments that are not options ("-" alone is one). Without a handler each is an error.
    CommandLine& positional(ValueHandler handler);
    // The one argument that is not an option, into `target`; a second is an error in the app's
    // words: "<twice> '<first>' and '<second>'" (twice: "more than one model given:").
    CommandLine& positional(std::string& target, std::string twice);

    // Reads argv[first] to argv[argc - 1]. Throws UsageError for an unknown option, an option
    // without its value, an unexpected positional argument, or what a handler throws.
    void parse(int argc, char** argv, int first = 1) const;
    void parse(const std::vector<std::string>& arguments) const;

    bool knows(const std::string& name) const;

private:
    struct Option
    {
        std::vector<std::string> names;
        bool takesValue = false;
        ValueHandler handler; // with no value: called with ""
    };
    const Option* find(const std::string& name) const;
    CommandLine& add(std::initializer_list<const char*> names, bool takesValue, ValueHandler handler);

    std::vector<Option> options_;
    ValueHandler positional_;
};

// What an app's main does with its command line: `parse` reads it and returns whether --help was
// asked. A UsageError goes to stderr as "<program>: <message>\n" followed by `afterError` (where to
// find the usage, or the usage itself): exit status 2; --help prints `usage` to stdout: exit status
// 0. Nothing when the program goes on; any other exception passes through.
std::optional<int> readCommandLine(const std::function<bool()>& parse, const std::string& program,
                                   const std::string& afterError, const std::string& usage);
// The same for an app's usual parser: `options = parse(argc, argv)`, whose `help` is --help.
template <class Options>
std::optional<int> readCommandLine(Options& options, Options (*parse)(int, char**), int argc, char** argv,
                                   const std::string& program, const std::string& afterError, const std::string& usage)
{
    return readCommandLine(
        [&]
        {
            options = parse(argc, argv);
            return options.help;
        },
        program, afterError, usage);
}

// Value parsers: `option` names the option in the error.

// Decimal digits only ("-1", " 7", "12abc" and "0x2" are errors), within [least, most].
std::uint64_t parseUnsigned(const std::string& option, const std::string& text, std::uint64_t least = 0,
                            std::uint64_t most = std::numeric_limits<std::uint64_t>::max());
// A finite decimal number ("inf" and "nan" are errors), within [least, most].
double parseNumber(const std::string& option, const std::string& text,
                   double least = -std::numeric_limits<double>::max(),
                   double most = std::numeric_limits<double>::max());
// "a,b,c" → {"a","b","c"}; empty items are kept ("a,,b", "a,") so a caller can refuse them.
std::vector<std::string> splitList(const std::string& text, char separator = ',');
// A non-empty list of unsigned integers within [least, most], e.g. "--speeds 1,2,4".
std::vector<unsigned> parseUnsignedList(const std::string& option, const std::string& text, unsigned least,
                                        unsigned most);
// WxH, each side from 1 to 16384.
void parseSize(const std::string& option, const std::string& text, unsigned& width, unsigned& height);
// x,y,z: three finite numbers.
std::array<double, 3> parseTriple(const std::string& option, const std::string& text);
// The command line as a shell would take it back (arguments with spaces or quotes quoted), for reports.
std::string quotedCommandLine(int argc, char** argv);
} // namespace osgVis::apps
