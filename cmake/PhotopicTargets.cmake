# photopic_library(NAME DIRS dir... [EXTRA_SOURCES f...] LINKS <target_link_libraries args>)
# Builds photopic_NAME (alias photopic::NAME) from every .cpp below the given folders, with the project's warnings,
# for the project's own targets (apps, tests, and the public shared library, which links the layers in
# privately). Headers are included as "layer/File.h" from src/; none of them is installed.
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
        return()
    endif()
    add_library(photopic_${name} STATIC ${sources} ${PL_EXTRA_SOURCES})
    add_library(photopic::${name} ALIAS photopic_${name})
    set_target_properties(photopic_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME photopic_${name})
    target_include_directories(photopic_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
    target_compile_features(photopic_${name} PUBLIC cxx_std_20)
    photopic_warnings(photopic_${name})
    if(PL_LINKS)
        target_link_libraries(photopic_${name} ${PL_LINKS})
    endif()
endfunction()

function(photopic_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
        -Wnon-virtual-dtor -Wold-style-cast -Woverloaded-virtual)
endfunction()

# photopic_embedded_shaders(OUT cpp KIND library|extra DIRS dir...)
# Generates `cpp` embedding every *.glsl below src/<dir> (cmake/EmbedShaders.cmake). KIND library: the table
# that gl/ShaderLibrary.h's embeddedShaders() serves; KIND extra: shaders that a target adds to it as it starts.
function(photopic_embedded_shaders)
    cmake_parse_arguments(PE "" "OUT;KIND" "DIRS" ${ARGN})
    set(shaders)
    foreach(dir ${PE_DIRS})
        file(GLOB_RECURSE found CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${dir}/*.glsl)
        list(APPEND shaders ${found})
    endforeach()
    string(REPLACE ";" "," dirs "${PE_DIRS}")
    add_custom_command(OUTPUT ${PE_OUT}
        COMMAND ${CMAKE_COMMAND} -DSRC_ROOT=${PROJECT_SOURCE_DIR}/src -DDIRS=${dirs} -DKIND=${PE_KIND}
                -DOUT=${PE_OUT} -P ${PROJECT_SOURCE_DIR}/cmake/EmbedShaders.cmake
        DEPENDS ${shaders} ${PROJECT_SOURCE_DIR}/cmake/EmbedShaders.cmake
        COMMENT "Embedding GLSL shaders of ${PE_DIRS}")
endfunction()
