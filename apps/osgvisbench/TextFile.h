// SPDX-License-Identifier: MIT
#pragma once
// Writes a report file whole, or throws std::runtime_error naming it ("cannot write the JSON report
// 'x'", "failed writing the JSON report 'x'"): a run never ends with a truncated file unreported.
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace osgVis::bench
{
template <class Write> void writeTextFile(const std::string& path, const std::string& what, Write write)
{
    std::ofstream file(path);
    if (!file)
        throw std::runtime_error("cannot write the " + what + " '" + path + "'");
    write(file);
    file.close();
    if (!file)
        throw std::runtime_error("failed writing the " + what + " '" + path + "'");
}

// The folder `path` and its parents unless it is one already, or std::runtime_error "cannot create
// the <what> 'path'" with the system's reason.
inline void createFolder(const std::string& path, const std::string& what)
{
    std::error_code error;
    std::filesystem::create_directories(path, error);
    if (!std::filesystem::is_directory(path))
        throw std::runtime_error("cannot create the " + what + " '" + path + "'" +
                                 (error ? ": " + error.message() : std::string()));
}
} // namespace osgVis::bench
