# Runs one packaging scenario with CMake in script mode (cmake -P):
#   MODE=find_package:     install crspline into a scratch prefix, then build
#                          find-package-test against it and run it; also check
#                          the pkg-config file and that an incompatible
#                          version request is refused.
#   MODE=add_subdirectory: build add-subdirectory-test, which vendors the tree.
# Variables: MODE, SOURCE_DIR (crspline), WORK_DIR (scratch), GENERATOR, CXX.
function(run)
    execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
        message(FATAL_ERROR "failed (${rc}): ${ARGV}\n${out}\n${err}")
    endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(common -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release)
set(here ${SOURCE_DIR}/tests/packaging)

if(MODE STREQUAL "find_package")
    set(prefix ${WORK_DIR}/prefix)
    run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/crspline ${common} -DCMAKE_INSTALL_PREFIX=${prefix}
        -DCRSPLINE_BUILD_TESTS=OFF -DCRSPLINE_BUILD_EXAMPLES=OFF -DCRSPLINE_BUILD_CLI=OFF)
    run(${CMAKE_COMMAND} --build ${WORK_DIR}/crspline)
    run(${CMAKE_COMMAND} --install ${WORK_DIR}/crspline)
    foreach(f include/crspline/crspline.hpp share/cmake/crspline/crspline-config.cmake
              share/cmake/crspline/crspline-config-version.cmake share/pkgconfig/crspline.pc)
        if(NOT EXISTS ${prefix}/${f})
            message(FATAL_ERROR "not installed: ${f}")
        endif()
    endforeach()
    run(${CMAKE_COMMAND} -S ${here}/find-package-test -B ${WORK_DIR}/consumer ${common} -DCMAKE_PREFIX_PATH=${prefix})
    run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
    run(${WORK_DIR}/consumer/consumer)
    # An incompatible version must not be found.
    file(WRITE ${WORK_DIR}/v9/CMakeLists.txt
         "cmake_minimum_required(VERSION 3.25)\nproject(v9 LANGUAGES CXX)\nfind_package(crspline 9.0 CONFIG REQUIRED)\n")
    execute_process(COMMAND ${CMAKE_COMMAND} -S ${WORK_DIR}/v9 -B ${WORK_DIR}/v9/build ${common}
                            -DCMAKE_PREFIX_PATH=${prefix}
                    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
    if(rc EQUAL 0)
        message(FATAL_ERROR "find_package(crspline 9.0) succeeded against version 0.1")
    endif()
elseif(MODE STREQUAL "add_subdirectory")
    run(${CMAKE_COMMAND} -S ${here}/add-subdirectory-test -B ${WORK_DIR}/consumer ${common}
        -DCRSPLINE_SOURCE_DIR=${SOURCE_DIR})
    run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
    run(${WORK_DIR}/consumer/consumer)
else()
    message(FATAL_ERROR "unknown MODE ${MODE}")
endif()
message(STATUS "packaging ${MODE}: ok")
