// SPDX-License-Identifier: MIT
#include "CommandLine.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace osgVis::apps
{
CommandLine& CommandLine::add(std::initializer_list<const char*> names, bool takesValue, ValueHandler handler)
{
    Option option;
    for (const char* name : names)
        option.names.emplace_back(name);
    option.takesValue = takesValue;
    option.handler = std::move(handler);
    options_.push_back(std::move(option));
    return *this;
}

CommandLine& CommandLine::flag(std::initializer_list<const char*> names, bool& target)
{
    return add(names, false, [&target](const std::string&) { target = true; });
}

CommandLine& CommandLine::flag(std::initializer_list<const char*> names, std::function<void()> handler)
{
    return add(names, false, [handler = std::move(handler)](const std::string&) { handler(); });
}

CommandLine& CommandLine::value(std::initializer_list<const char*> names, std::string& target)
{
    return add(names, true, [&target](const std::string& text) { target = text; });
}

CommandLine& CommandLine::value(std::initializer_list<const char*> names, ValueHandler handler)
{
    return add(names, true, std::move(handler));
}

CommandLine& CommandLine::positional(ValueHandler handler)
{
    positional_ = std::move(handler);
    return *this;
}

CommandLine& CommandLine::positional(std::string& target, std::string twice)
{
    return positional(
        [&target, twice = std::move(twice)](const std::string& value)
        {
            if (!target.empty())
                throw UsageError(twice + " '" + target + "' and '" + value + "'");
            target = value;
        });
}

const CommandLine::Option* CommandLine::find(const std::string& name) const
{
    for (const Option& option : options_)
        for (const std::string& known : option.names)
            if (known == name)
                return &option;
    return nullptr;
}

bool CommandLine::knows(const std::string& name) const
{
    return find(name) != nullptr;
}

void CommandLine::parse(const std::vector<std::string>& arguments) const
{
    for (std::size_t i = 0; i < arguments.size(); ++i)
    {
        const std::string& argument = arguments[i];
        const bool isOption = argument.size() > 1 && argument[0] == '-';
        if (!isOption)
        {
            if (!positional_)
                throw UsageError("unexpected argument '" + argument + "' (see --help)");
            positional_(argument);
            continue;
        }
        const Option* option = find(argument);
        if (!option)
            throw UsageError("unknown option '" + argument + "' (see --help)");
        if (!option->takesValue)
        {
            option->handler("");
            continue;
        }
        if (i + 1 >= arguments.size())
            throw UsageError(argument + " expects a value");
        option->handler(arguments[++i]);
    }
}

void CommandLine::parse(int argc, char** argv, int first) const
{
    parse(std::vector<std::string>(argv + std::min(first, argc), argv + argc));
}

std::optional<int> readCommandLine(const std::function<bool()>& parse, const std::string& program,
                                   const std::string& afterError, const std::string& usage)
{
    bool help = false;
    try
    {
        help = parse();
    }
    catch (const UsageError& e)
    {
        std::cerr << program << ": " << e.what() << "\n" << afterError;
        return 2;
    }
    if (!help)
        return std::nullopt;
    std::cout << usage;
    return 0;
}

std::uint64_t parseUnsigned(const std::string& option, const std::string& text, std::uint64_t least,
                            std::uint64_t most)
{
    const bool digits = !text.empty() && text.size() <= 19 && text.find_first_not_of("0123456789") == std::string::npos;
    if (!digits)
        throw UsageError(option + " expects a non-negative integer, got '" + text + "'");
    const std::uint64_t value = std::strtoull(text.c_str(), nullptr, 10);
    if (value < least || value > most)
        throw UsageError(option + " must lie between " + std::to_string(least) + " and " + std::to_string(most) +
                         ", got '" + text + "'");
    return value;
}

double parseNumber(const std::string& option, const std::string& text, double least, double most)
{
    // note: strtod also reads hexadecimal, "inf" and "nan"; only decimal forms are numbers here.
    const bool decimal = !text.empty() && text.find_first_not_of("0123456789.eE+-") == std::string::npos;
    char* end = nullptr;
    const double value = decimal ? std::strtod(text.c_str(), &end) : 0.0;
    if (!decimal || end != text.c_str() + text.size() || !std::isfinite(value))
        throw UsageError(option + " expects a number, got '" + text + "'");
    if (value < least || value > most)
    {
        std::ostringstream range;
        range << option << " must lie between " << least << " and " << most << ", got '" << text << "'";
        throw UsageError(range.str());
    }
    return value;
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

std::vector<unsigned> parseUnsignedList(const std::string& option, const std::string& text, unsigned least,
                                        unsigned most)
{
    std::vector<unsigned> values;
    for (const std::string& item : splitList(text, ','))
        values.push_back(unsigned(parseUnsigned(option, item, least, most)));
    if (values.empty())
        throw UsageError(option + " is empty");
    return values;
}

void parseSize(const std::string& option, const std::string& text, unsigned& width, unsigned& height)
{
    const std::size_t x = text.find_first_of("xX");
    if (x == std::string::npos)
        throw UsageError(option + " expects WxH (e.g. 1024x768), got '" + text + "'");
    try
    {
        width = unsigned(parseUnsigned(option, text.substr(0, x), 1, 16384));
        height = unsigned(parseUnsigned(option, text.substr(x + 1), 1, 16384));
    }
    catch (const UsageError&)
    {
        throw UsageError(option + " must lie between 1x1 and 16384x16384, got '" + text + "'");
    }
}

std::array<double, 3> parseTriple(const std::string& option, const std::string& text)
{
    const std::vector<std::string> parts = splitList(text, ',');
    std::array<double, 3> values{};
    try
    {
        if (parts.size() != 3)
            throw UsageError("");
        for (int i = 0; i < 3; ++i)
            values[i] = parseNumber(option, parts[i]);
    }
    catch (const UsageError&)
    {
        throw UsageError(option + " expects x,y,z (three numbers), got '" + text + "'");
    }
    return values;
}

std::string quotedCommandLine(int argc, char** argv)
{
    std::string line;
    for (int i = 0; i < argc; ++i)
    {
        const std::string argument = argv[i];
        std::string quoted = argument;
        if (argument.empty() || argument.find_first_of(" \t\"'\\$") != std::string::npos)
        {
            quoted = "'";
            for (char c : argument)
                quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
            quoted += "'";
        }
        line += (i ? " " : "") + quoted;
    }
    return line;
}
} // namespace osgVis::apps
