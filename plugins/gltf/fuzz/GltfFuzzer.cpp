// SPDX-License-Identifier: MIT
// libFuzzer entry point: every input through the glTF reader's stream path must give a node or an
// error. Seed it with the sample models: osgvis_gltf_fuzzer corpus/ /usr/share/assimp/models/glTF2/...
#include <osg/Notify>
#include <osgDB/Registry>

#include <cstdint>
#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static osgDB::ReaderWriter* reader = [] {
        osg::setNotifyLevel(osg::FATAL); // tinygltf's warnings on mutants would drown the fuzzer's output
        return osgDB::Registry::instance()->getReaderWriterForExtension("gltf");
    }();
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    osgDB::ReaderWriter::ReadResult result = reader->readNode(in, nullptr);
    if (!result.validNode() && result.message().empty())
        __builtin_trap(); // neither a node nor an error message
    return 0;
}
