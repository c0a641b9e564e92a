# Enforces the layering of docs/architecture.md on the #include lines: every folder of src/ (and
# the public headers and the CLI) may include only the folders listed for it. Run with
#   cmake -DROOT=<source dir> -P check_layers.cmake
# It fails with the offending file and include, so that an include that runs back up a layer
# (or a format that includes a solver) is caught in the default test suite.

cmake_minimum_required(VERSION 3.25)

set(allowed_model "model")
set(allowed_core "core")
set(allowed_grid "")
set(allowed_physics "physics")
set(allowed_lookup "lookup")
set(allowed_elastic "elastic;core;grid")
set(allowed_elastic/operators "elastic;core;grid")
set(allowed_geometry "geometry;elastic;grid")
set(allowed_normal "normal;elastic;core;grid")
set(allowed_tangential "tangential;physics;elastic;core;grid")
set(allowed_simplified "simplified;tangential;physics;geometry;elastic;core;grid")
set(allowed_post "post;elastic;core;grid")
set(allowed_contact "contact;post;simplified;tangential;physics;normal;geometry;elastic;core;grid")
set(allowed_wheelrail "wheelrail;contact;post;simplified;tangential;physics;normal;geometry;elastic;core;grid")
set(allowed_dynamics "dynamics")
# The FE advice solves through the public API (rollcontact/solve.hpp) only.
set(allowed_fe_advice "fe_advice")
set(allowed_format/text "format/text")
set(allowed_format/profiles "format/profiles;format/text")
set(allowed_format/inp "format/inp;format/profiles;format/text")
set(allowed_format/toml "format/toml;format/inp;format/profiles;format/text")
set(allowed_format/report "format/report;format/inp;format/text")
set(allowed_format/hdf5 "format/hdf5;format/text")
set(allowed_batch "batch;format/text;format/profiles;format/inp;format/toml;format/report;format/hdf5;lookup;wheelrail;contact;post;simplified;tangential;physics;normal;geometry;elastic;core;grid")

set(allowed_bindings/c "bindings;lookup;format/hdf5;format/inp;format/profiles;format/text;wheelrail;contact;post;simplified;tangential;physics;normal;geometry;elastic;core;grid")
set(allowed_bindings/python "bindings;lookup;format/hdf5;batch;format/toml;format/inp;format/text;format/report;format/profiles;wheelrail;contact;post;simplified;tangential;physics;normal;geometry;elastic;core;grid")

set(violations "")
function(check_folder folder files)
  foreach(f IN LISTS files)
    file(STRINGS "${f}" lines REGEX "^#include \"")
    foreach(line IN LISTS lines)
      string(REGEX MATCH "^#include \"([^\"]+)\"" _ "${line}")
      set(path "${CMAKE_MATCH_1}")
      if(path MATCHES "^rollcontact/")  # the public API: allowed everywhere
        continue()
      endif()
      if(path MATCHES "^support/")  # test support (tests only)
        continue()
      endif()
      string(REGEX MATCH "^(format/[a-z_]+|[a-z_]+)/" _ "${path}")
      set(target "${CMAKE_MATCH_1}")
      if(NOT target)
        continue()  # a file of the same folder, included without a folder
      endif()
      if(NOT target IN_LIST allowed_${folder})
        list(APPEND violations "${f}: ${folder} includes ${path}")
        set(violations "${violations}" PARENT_SCOPE)
      endif()
    endforeach()
  endforeach()
endfunction()

foreach(folder model core grid physics lookup elastic elastic/operators geometry normal tangential simplified post contact wheelrail
               dynamics fe_advice format/text format/profiles format/inp format/toml format/report format/hdf5 batch
               bindings/c bindings/python)
  file(GLOB files "${ROOT}/src/${folder}/*.hpp" "${ROOT}/src/${folder}/*.cpp")
  check_folder(${folder} "${files}")
endforeach()

# Public headers include only public headers; the CLI only formats and batch work.
set(allowed_include "")
file(GLOB_RECURSE files "${ROOT}/include/*.hpp" "${ROOT}/include/*.h")
check_folder(include "${files}")
set(allowed_apps "format/text;format/inp;format/toml;format/report;format/profiles;format/hdf5;batch")
file(GLOB files "${ROOT}/apps/rollcontact/*.cpp" "${ROOT}/apps/rollcontact/*.hpp")
check_folder(apps "${files}")

if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layering violations:\n  ${text}")
endif()
message(STATUS "layering: every include goes down a layer")
