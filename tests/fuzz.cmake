# turf_fuzz(<name> SOURCES <files> [PROTOS <protos>] [IDL <types>] [INCLUDES <dirs>] [DEFINES <NAME=value>]
#           [LIBS <libs>] [DEPENDS <targets>])
# PROTOS ssl_vision ...: the generated codecs/proto/<name>.pb.cc (with protobuf); IDL Common Clock ...: the
# generated turf/idl/<name>.cxx (with Fast CDR); their include directories and build targets come with them.
# Builds a libFuzzer target with clang (ASan + UBSan) from the listed sources
# and registers ctest `fuzz_<name>`, which fuzzes for TURF_FUZZ_SECONDS (10 s).
# Seeds: tests/fuzz/seeds/<name>/ (read only); new inputs go to the build tree.
# Without clang the test is registered and reports itself skipped.
# Longer runs on demand: build/tests/fuzz_<name> -max_total_time=600 <corpus dirs>
find_program(TURF_CLANGXX NAMES clang++-14 clang++)
set(TURF_FUZZ_SECONDS 10 CACHE STRING "seconds each fuzz test runs in ctest")

function(turf_fuzz name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PROTOS;IDL;INCLUDES;DEFINES;LIBS;DEPENDS" ${ARGN})
  if(ARG_PROTOS)
    set(gen ${CMAKE_BINARY_DIR}/codecs/proto/gen)
    foreach(proto ${ARG_PROTOS})
      list(APPEND ARG_SOURCES ${gen}/codecs/proto/${proto}.pb.cc)
    endforeach()
    list(APPEND ARG_INCLUDES ${gen})
    list(APPEND ARG_LIBS -lprotobuf)
    list(APPEND ARG_DEPENDS turf_ssl_proto)
  endif()
  if(ARG_IDL)
    set(gen ${CMAKE_BINARY_DIR}/idl/gen)
    foreach(type ${ARG_IDL})
      list(APPEND ARG_SOURCES ${gen}/turf/idl/${type}.cxx)
    endforeach()
    list(APPEND ARG_INCLUDES ${gen})
    list(APPEND ARG_LIBS -lfastcdr)
    list(APPEND ARG_DEPENDS turf_idl)
  endif()
  if(NOT TURF_CLANGXX)
    add_test(NAME fuzz_${name} COMMAND ${CMAKE_COMMAND} -E echo "clang++ not found: fuzz_${name} skipped")
    set_tests_properties(fuzz_${name} PROPERTIES SKIP_REGULAR_EXPRESSION "skipped")
    return()
  endif()
  set(bin ${CMAKE_BINARY_DIR}/tests/fuzz_${name})
  set(flags -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined)
  set(includes "")
  foreach(dir ${ARG_INCLUDES} ${PROJECT_SOURCE_DIR})
    list(APPEND includes -I${dir})
  endforeach()
  foreach(definition ${ARG_DEFINES})
    list(APPEND includes -D${definition})
  endforeach()
  add_custom_command(
    OUTPUT ${bin}
    COMMAND ${TURF_CLANGXX} ${flags} ${includes} ${ARG_SOURCES} -o ${bin} ${ARG_LIBS}
    DEPENDS ${ARG_SOURCES} ${ARG_DEPENDS}
    COMMENT "clang libFuzzer target fuzz_${name}"
    VERBATIM)
  add_custom_target(fuzz_${name}_build ALL DEPENDS ${bin})
  set(corpus ${CMAKE_BINARY_DIR}/tests/fuzz_corpus/${name})
  set(seeds ${PROJECT_SOURCE_DIR}/tests/fuzz/seeds/${name})
  file(MAKE_DIRECTORY ${corpus} ${seeds})
  add_test(NAME fuzz_${name}
           COMMAND ${bin} -max_total_time=${TURF_FUZZ_SECONDS} -max_len=65536 -rss_limit_mb=2048 ${corpus} ${seeds})
endfunction()
