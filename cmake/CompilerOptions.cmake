# Warning flags for every rollcontact target; -Werror when ROLLCONTACT_WERROR is on (CI).
add_library(rollcontact_warnings INTERFACE)
target_compile_options(rollcontact_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Wnon-virtual-dtor
  -Wold-style-cast -Woverloaded-virtual -Wimplicit-fallthrough
  $<$<BOOL:${ROLLCONTACT_WERROR}>:-Werror>
  # GCC 12 reports false -Wrestrict positives inside libstdc++'s std::string operator+ at -O2/-O3
  # (GCC bug 105329); the warning says nothing about our code there.
  $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)

if(ROLLCONTACT_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  # With the sanitizer instrumentation GCC 12 reports false -Wmaybe-uninitialized inside
  # libstdc++ (<regex>, std::function); the release build keeps the warning.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
  add_link_options(-fsanitize=address,undefined)
endif()

if(ROLLCONTACT_SANITIZE_THREAD)
  # ThreadSanitizer: the C library's concurrent handles (tests/cntc/test_cntc_threads.cpp).
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()

if(ROLLCONTACT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "ROLLCONTACT_FUZZ needs clang (libFuzzer): use the preset `fuzz`")
  endif()
  # Coverage instrumentation for every library; the harnesses link libFuzzer's main.
  add_compile_options(-fsanitize=fuzzer-no-link)
  add_link_options(-fsanitize=fuzzer-no-link)
endif()

# rollcontact_add_module(<folder> DEPS <libs...>): one static library per src/ folder, so the
# layering of ARCHITECTURE.md is enforced by the linker (grid <- elastic <- normal, ...).
function(rollcontact_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  file(GLOB _srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  add_library(rollcontact_${name} STATIC ${_srcs})
  # src/ is an include path of the build only: installed, a library exposes include/ alone.
  target_include_directories(rollcontact_${name}
    PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(rollcontact_${name} PUBLIC ${ARG_DEPS}
                        PRIVATE $<BUILD_INTERFACE:rollcontact_warnings>)
  set_property(GLOBAL APPEND PROPERTY ROLLCONTACT_LIBRARIES rollcontact_${name})
  set_target_properties(rollcontact_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()
