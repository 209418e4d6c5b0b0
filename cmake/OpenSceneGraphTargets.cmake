# SPDX-License-Identifier: MIT
# OSG 3.6 ships no CMake package and FindOpenSceneGraph only sets variables; wrap them in imported
# targets OpenSceneGraph::<component> so the rest of the build (and consumers) link targets.
include_guard(GLOBAL)
set(_osgvis_osg_components osg OpenThreads osgDB osgUtil osgGA osgViewer osgText)
find_package(OpenSceneGraph 3.6 REQUIRED COMPONENTS osgDB osgUtil osgGA osgViewer osgText)
find_package(OpenGL REQUIRED)
foreach(_c IN LISTS _osgvis_osg_components)
    string(TOUPPER ${_c} _C)
    if(NOT TARGET OpenSceneGraph::${_c})
        set(_lib "${${_C}_LIBRARY}")
        if(NOT _lib)
            set(_lib "${${_C}_LIBRARY_RELEASE}")
        endif()
        if(NOT _lib)
            message(FATAL_ERROR "OpenSceneGraph component ${_c} not found (install libopenscenegraph-dev)")
        endif()
        add_library(OpenSceneGraph::${_c} UNKNOWN IMPORTED)
        set_target_properties(OpenSceneGraph::${_c} PROPERTIES
            IMPORTED_LOCATION "${_lib}"
            INTERFACE_INCLUDE_DIRECTORIES "${OPENSCENEGRAPH_INCLUDE_DIRS}")
    endif()
endforeach()
set_property(TARGET OpenSceneGraph::osg APPEND PROPERTY INTERFACE_LINK_LIBRARIES OpenSceneGraph::OpenThreads OpenGL::GL)
set_property(TARGET OpenSceneGraph::osgDB APPEND PROPERTY INTERFACE_LINK_LIBRARIES OpenSceneGraph::osg)
set_property(TARGET OpenSceneGraph::osgUtil APPEND PROPERTY INTERFACE_LINK_LIBRARIES OpenSceneGraph::osg)
set_property(TARGET OpenSceneGraph::osgGA APPEND PROPERTY INTERFACE_LINK_LIBRARIES OpenSceneGraph::osgDB OpenSceneGraph::osgUtil)
set_property(TARGET OpenSceneGraph::osgText APPEND PROPERTY INTERFACE_LINK_LIBRARIES OpenSceneGraph::osgDB)
set_property(TARGET OpenSceneGraph::osgViewer APPEND PROPERTY INTERFACE_LINK_LIBRARIES
    OpenSceneGraph::osgGA OpenSceneGraph::osgText OpenSceneGraph::osgUtil OpenSceneGraph::osgDB)
# where osgDB looks for plugins: osgPlugins-<version> beside the libraries
set(OSGVIS_OSG_PLUGIN_DIRNAME "osgPlugins-${OPENSCENEGRAPH_VERSION}")
