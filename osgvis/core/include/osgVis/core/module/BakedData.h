// SPDX-License-Identifier: MIT
#pragma once
/// @file
/// Data baked for one model (cell-portal data, view cells, ...), handed to a chain by whoever holds
/// the model (issue 46): a VisibilityGroup read from a `.pvs` file carries its own, so two groups of
/// the same model may hold different bakes and the data go when the group goes. Each module takes
/// the kinds it knows (VisibilityModule::setBakedData); a kind is its C++ type. Data a module is
/// given win over what the process-wide BakedDataStore holds for the same scene.
#include <map>
#include <memory>
#include <typeindex>

namespace osgVis::core
{
class BakedData
{
public:
    /// Replaces the data of this kind; null removes them.
    template <class Data> void set(std::shared_ptr<const Data> data)
    {
        if (data)
            _byKind[std::type_index(typeid(Data))] = std::move(data);
        else
            _byKind.erase(std::type_index(typeid(Data)));
    }
    template <class Data> std::shared_ptr<const Data> get() const
    {
        const auto found = _byKind.find(std::type_index(typeid(Data)));
        return found == _byKind.end() ? nullptr : std::static_pointer_cast<const Data>(found->second);
    }
    bool empty() const { return _byKind.empty(); }

private:
    std::map<std::type_index, std::shared_ptr<const void>> _byKind;
};
} // namespace osgVis::core
