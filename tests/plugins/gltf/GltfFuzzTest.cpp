// SPDX-License-Identifier: MIT
// Mutation fuzzing of the glTF reader (deterministic seed): byte flips, truncations, duplicated and
// deleted chunks and numbers replaced by extreme values, on .gltf JSON and on a .glb's JSON chunk
// (its lengths fixed up so the mutant gets past the header) as well as its raw bytes. Each mutant is
// read from memory; every result must be a node or an error with a message — a crash or hang fails
// the whole binary.
#include "GltfTestModels.h"

#include <osg/Notify>
#include <osgDB/Options>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <iostream>
#include <random>
#include <sstream>

using namespace osgVis::test::gltf;

namespace
{
class Mutator
{
public:
    explicit Mutator(std::uint32_t seed) : _random(seed) {}

    std::string mutate(std::string text)
    {
        const unsigned steps = 1 + below(3);
        for (unsigned i = 0; i < steps && !text.empty(); ++i)
        {
            switch (below(5))
            {
            case 0: // flip a few bytes
                for (unsigned n = 1 + below(4); n > 0; --n)
                    text[below(text.size())] = char(below(256));
                break;
            case 1: // truncate
                text.resize(below(text.size()));
                break;
            case 2: // duplicate a chunk somewhere
            {
                const std::size_t begin = below(text.size());
                const std::string chunk = text.substr(begin, 1 + below(200));
                text.insert(below(text.size() + 1), chunk);
                break;
            }
            case 3: // delete a chunk
                text.erase(below(text.size()), 1 + below(200));
                break;
            default:
                replaceNumber(text);
            }
        }
        return text;
    }

    std::size_t below(std::size_t n) { return n == 0 ? 0 : std::size_t(_random() % n); }

private:
    // A run of digits somewhere after a random position becomes a huge, negative or odd value.
    void replaceNumber(std::string& text)
    {
        static const char* const values[] = {"4294967295", "-1", "99999999999999999999", "1e308", "-2147483648",
                                             "0", "18446744073709551615", "2147483647", "65536", "3.5", "-0", "1e-9"};
        const std::size_t start = text.find_first_of("0123456789", below(text.size()));
        if (start == std::string::npos)
            return;
        const std::size_t end = text.find_first_not_of("0123456789.", start);
        text.replace(start, (end == std::string::npos ? text.size() : end) - start,
                     values[below(sizeof(values) / sizeof(values[0]))]);
    }

    std::mt19937 _random;
};

// A .glb with its JSON chunk replaced, the chunk and file lengths fixed up (padding with spaces as
// glTF does), so JSON mutants reach the parser behind the binary header.
std::string withJsonChunk(const std::string& glb, std::string json)
{
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, glb.data() + 12, 4);
    const std::string rest = glb.substr(20 + jsonLength);
    while (json.size() % 4 != 0)
        json += ' ';
    std::string out = glb.substr(0, 20) + json + rest;
    const std::uint32_t total = std::uint32_t(out.size()), chunk = std::uint32_t(json.size());
    std::memcpy(&out[8], &total, 4);
    std::memcpy(&out[12], &chunk, 4);
    return out;
}

std::string jsonChunk(const std::string& glb)
{
    std::uint32_t jsonLength = 0;
    std::memcpy(&jsonLength, glb.data() + 12, 4);
    return glb.substr(20, jsonLength);
}

struct Outcomes
{
    unsigned nodes = 0, errors = 0;
};

// Reads `bytes` as a stream; fails the test when the result is neither a node nor an explained error.
void readMutant(const std::string& bytes, const osgDB::Options* options, Outcomes& outcomes)
{
    std::istringstream in(bytes);
    osgDB::ReaderWriter::ReadResult result = gltfReader().readNode(in, options);
    if (result.validNode())
        ++outcomes.nodes;
    else
    {
        ++outcomes.errors;
        ASSERT_TRUE(result.error()) << "status " << result.status();
        ASSERT_EQ(result.message().rfind("gltf: <stream>: ", 0), 0u) << result.message();
    }
}

class QuietOsg
{
public:
    QuietOsg() : _level(osg::getNotifyLevel()) { osg::setNotifyLevel(osg::FATAL); }
    ~QuietOsg() { osg::setNotifyLevel(_level); }

private:
    osg::NotifySeverity _level;
};

constexpr unsigned MutantsPerSeed = 3000;
} // namespace

TEST(GltfFuzz, JsonMutantsGiveNodesOrErrors)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    QuietOsg quiet;
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setDatabasePath(samplePath("glTF-Asset-Generator/Mesh_PrimitiveMode"));
    Mutator mutator(20261123);
    Outcomes outcomes;
    for (const char* file : {"BoxTextured-glTF-Embedded/BoxTextured.gltf",
                             "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_13.gltf"})
    {
        const std::string original = fileBytes(samplePath(file));
        ASSERT_FALSE(original.empty()) << file;
        for (unsigned i = 0; i < MutantsPerSeed; ++i)
        {
            readMutant(mutator.mutate(original), options.get(), outcomes);
            if (HasFatalFailure())
                return;
        }
    }
    std::cout << outcomes.nodes << " mutants read as nodes, " << outcomes.errors << " as errors\n";
    // Both outcomes occur: the mutants are neither all harmless nor all rejected outright.
    EXPECT_GT(outcomes.nodes, 0u);
    EXPECT_GT(outcomes.errors, 0u);
}

TEST(GltfFuzz, GlbMutantsGiveNodesOrErrors)
{
    OSGVIS_REQUIRE_GLTF_SAMPLES();
    QuietOsg quiet;
    Mutator mutator(7);
    Outcomes outcomes;
    const std::string glb = fileBytes(samplePath("BoxTextured-glTF-Binary/BoxTextured.glb"));
    ASSERT_GT(glb.size(), 20u);
    const std::string json = jsonChunk(glb);
    for (unsigned i = 0; i < MutantsPerSeed; ++i)
    {
        // Half the mutants change the JSON inside a valid container, half the raw bytes.
        const std::string mutant = i % 2 == 0 ? withJsonChunk(glb, mutator.mutate(json)) : mutator.mutate(glb);
        readMutant(mutant, nullptr, outcomes);
        if (HasFatalFailure())
            return;
    }
    std::cout << outcomes.nodes << " mutants read as nodes, " << outcomes.errors << " as errors\n";
    EXPECT_GT(outcomes.nodes, 0u);
    EXPECT_GT(outcomes.errors, 0u);
}
