# photopic_library(NAME DIRS dir... [EXTRA_SOURCES f...] LINKS <target_link_libraries args>)
# Builds photopic_NAME (alias photopic::NAME) from every .cpp below the given folders, with the project's warnings,
# and installs it into the exported package. Headers are included as "layer/File.h" from src/ (and from
# include/photopic once installed).
function(photopic_library name)
    cmake_parse_arguments(PL "" "" "DIRS;EXTRA_SOURCES;LINKS" ${ARGN})
    set(sources)
    foreach(dir ${PL_DIRS})
        file(GLOB_RECURSE found CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${dir}/*.cpp)
        list(APPEND sources ${found})
    endforeach()
    if(NOT sources AND NOT PL_EXTRA_SOURCES)
        # A layer with no code yet: an empty interface target keeps its dependants' link lines valid.
        add_library(photopic_${name} INTERFACE)
        add_library(photopic::${name} ALIAS photopic_${name})
        set_target_properties(photopic_${name} PROPERTIES EXPORT_NAME ${name})
        string(REPLACE "PRIVATE" "INTERFACE" links "${PL_LINKS}")
        string(REPLACE "PUBLIC" "INTERFACE" links "${links}")
        target_link_libraries(photopic_${name} ${links})
        install(TARGETS photopic_${name} EXPORT photopicTargets)
        return()
    endif()
    add_library(photopic_${name} STATIC ${sources} ${PL_EXTRA_SOURCES})
    add_library(photopic::${name} ALIAS photopic_${name})
    set_target_properties(photopic_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME photopic_${name})
    target_include_directories(photopic_${name} PUBLIC
        $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
        $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/photopic>
        $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    target_compile_features(photopic_${name} PUBLIC cxx_std_20)
    photopic_warnings(photopic_${name})
    if(PL_LINKS)
        target_link_libraries(photopic_${name} ${PL_LINKS})
    endif()
    install(TARGETS photopic_${name} EXPORT photopicTargets)
endfunction()

function(photopic_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
        -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual)
endfunction()
