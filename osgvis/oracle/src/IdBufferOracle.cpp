// SPDX-License-Identifier: MIT
#include <osgVis/oracle/IdBufferOracle.h>

#include "IdColour.h"
#include "IdPassState.h"
#include "IdRenderer.h"
#include "ObjectChain.h"

#include <algorithm>
#include <stdexcept>

namespace osgVis::oracle
{
IdBufferOracle::IdBufferOracle(osg::Node* root, const OracleSettings& settings)
    : _settings(settings)
{
    if (!root)
        throw std::invalid_argument("osgVis oracle: null root");
    if (settings.width == 0 || settings.height == 0)
        throw std::invalid_argument("osgVis oracle: empty image size");
    _objects = enumerateObjects(*root);
    if (_objects.size() > MaxIdObjects)
        throw std::runtime_error("osgVis oracle: more objects than 24-bit ids");

    std::vector<std::pair<std::uint32_t, osg::ref_ptr<osg::Node>>> opaque, transparent;
    for (std::uint32_t i = 0; i < _objects.size(); ++i)
        (_objects[i].transparent ? transparent : opaque).emplace_back(i, createObjectChain(_objects[i], i));

    const IdPassState pass = createIdPassState();
    _display = std::make_unique<IdRenderer>(settings.width, settings.height, pass, opaque, transparent,
                                            _objects.size());
    if (settings.supersample > 1)
        _supersampled = std::make_unique<IdRenderer>(settings.width * settings.supersample,
                                                     settings.height * settings.supersample, pass, opaque,
                                                     transparent, _objects.size());
    _seenDisplay.resize(_objects.size());
    _seenSupersampled.resize(_objects.size());
}

IdBufferOracle::~IdBufferOracle() = default;

IdBufferOracle::Result IdBufferOracle::visible(const osg::Matrixd& view, const osg::Matrixd& projection)
{
    std::fill(_seenDisplay.begin(), _seenDisplay.end(), 0);
    std::fill(_seenSupersampled.begin(), _seenSupersampled.end(), 0);
    _pixelsDisplay.assign(_objects.size(), 0);
    _display->render(view, projection, _seenDisplay, &_pixelsDisplay);
    if (_supersampled)
        _supersampled->render(view, projection, _seenSupersampled);

    Result result;
    for (std::uint32_t i = 0; i < _objects.size(); ++i)
    {
        if (_seenDisplay[i])
        {
            result.visible.push_back(i);
            result.pixels.push_back(_pixelsDisplay[i]);
        }
        else if (_seenSupersampled[i])
        {
            result.visible.push_back(i);
            result.pixels.push_back(0);
            ++result.onlyInSupersampled;
        }
    }
    return result;
}
} // namespace osgVis::oracle
