#pragma once
// The async and extraction options of a VisibilityGroup as far as its API lets them be read back.
// note: VisibilityGroup has setters but (so far) no getters for them; where the getters are missing,
// canReadOptions is false and the readers below answer the defaults, so the wrapper leaves those
// properties out of written files rather than writing them wrong. Reading them works either way.
#include <osgVis/VisibilityGroup>

#include <type_traits>
#include <utility>

namespace osgVis::serializers
{
template <class Group, class = void>
struct HasOptionGetters : std::false_type
{
};
template <class Group>
struct HasOptionGetters<Group, std::void_t<decltype(std::declval<const Group&>().getAsyncOptions()),
                                           decltype(std::declval<const Group&>().getExtractionOptions())>>
    : std::true_type
{
};
constexpr bool canReadOptions = HasOptionGetters<VisibilityGroup>::value;

template <class Group = VisibilityGroup>
core::AsyncOptions asyncOptionsOf(const Group& group)
{
    if constexpr (HasOptionGetters<Group>::value)
        return group.getAsyncOptions();
    else
        return {};
}

template <class Group = VisibilityGroup>
ExtractionOptions extractionOptionsOf(const Group& group)
{
    if constexpr (HasOptionGetters<Group>::value)
        return group.getExtractionOptions();
    else
        return {};
}
} // namespace osgVis::serializers
