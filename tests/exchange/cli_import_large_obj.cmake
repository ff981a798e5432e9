# A 160 MB OBJ imports within 1 GiB (cmake -P). The file is made here, at test time (never
# committed): 20 million `v` lines (the most vertices 160 MB can hold, 8 bytes each) and one
# bilinear surface naming the first, two middle and the last of them. `isoparm import` runs
# under `ulimit -v 1048576` (1 GiB of address space: its peak resident memory can only be
# lower), and where /usr/bin/time is installed its peak resident size is printed too. Before
# the reader streamed its statements it tokenised the whole file first and peaked at 3.3 GB
# (under the cap: SIGABRT from std::bad_alloc). The scene written must hold the surface with
# the four vertices' values, read back from the text.
cmake_minimum_required(VERSION 3.25)
foreach(var ISOPARM WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "cli_import_large_obj.cmake: -D${var}=... is missing")
  endif()
endforeach()
if(SANITIZE)
  message(STATUS "skipped: AddressSanitizer cannot start inside an address-space limit")
  return()
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(obj ${WORK}/large.obj)

# 20 blocks of 1,000,000 lines; the first line of the file, of block 11 and the last line of
# the file carry distinct values so that the surface's points show which vertices were read.
string(REPEAT "v 1 2 3\n" 999999 block)
file(WRITE ${obj} "v 0 0 0\n${block}")
foreach(k RANGE 2 20)
  if(k EQUAL 11)
    file(APPEND ${obj} "v 5 0 1\nv 0 5 2\n")
    string(REPEAT "v 1 2 3\n" 999998 middle)
    file(APPEND ${obj} "${middle}")
  elseif(k EQUAL 20)
    file(APPEND ${obj} "${block}v 5 5 3\n")
  else()
    file(APPEND ${obj} "v 1 2 3\n${block}")
  endif()
endforeach()
# Vertices 10,000,001 and 10,000,002 are the first two lines of block 11; -1 is the last.
file(APPEND ${obj} "cstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 10000001 10000002 -1\n"
                   "parm u 0 0 1 1\nparm v 0 0 1 1\nend\n")
file(SIZE ${obj} bytes)
if(bytes LESS 160000000)
  message(FATAL_ERROR "the generated OBJ has ${bytes} bytes, expected 160 MB")
endif()

set(timer "")
if(EXISTS /usr/bin/time)
  set(timer /usr/bin/time -f "peak resident %M KiB, %e s")
endif()
execute_process(COMMAND sh -c "ulimit -v 1048576 && exec \"$0\" \"$@\"" ${timer} ${ISOPARM}
                        import ${obj} -o ${WORK}/large.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 240)
file(REMOVE ${obj})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "a ${bytes}-byte OBJ did not import under ulimit -v 1048576 (1 GiB): "
                      "exit '${rc}'\n${out}\n${err}")
endif()
message(STATUS "${bytes}-byte OBJ imported under ulimit -v 1048576: ${err}")
if(err MATCHES "peak resident ([0-9]+) KiB")
  if(CMAKE_MATCH_1 GREATER_EQUAL 1048576)
    message(FATAL_ERROR "the import's peak resident size is ${CMAKE_MATCH_1} KiB, not under 1 GiB")
  endif()
endif()

file(READ ${WORK}/large.json scene)
string(JSON count LENGTH "${scene}" objects)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "the scene holds ${count} objects, expected the one surface")
endif()
string(JSON points GET "${scene}" objects 0 surface points)
string(REGEX REPLACE "[ \n]" "" points "${points}")
# points[i][j] is u index i, v index j (the OBJ lists u fastest: 1, 10000001 are v = 0).
set(expected "[[[0.0,0.0,0.0],[0.0,5.0,2.0]],[[5.0,0.0,1.0],[5.0,5.0,3.0]]]")
if(NOT points STREQUAL expected)
  message(FATAL_ERROR "the surface's points are ${points}, expected ${expected}")
endif()
file(REMOVE_RECURSE ${WORK})
