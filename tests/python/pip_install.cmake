# cmake -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -DPYTHON=/usr/bin/python3 [-DMODULE=<_crspline.so>] -P pip_install.cmake
#
# Installs the Python package the way a user would, offline:
#   python3 -m venv --system-site-packages venv
#   venv/bin/pip install --no-build-isolation --no-index ./python
# from a copy of the sources (so that scikit-build's _skbuild/ and the
# egg-info land in the scratch folder, not in the source tree), then imports
# it from the venv with a clean environment and checks it works.
# With MODULE (CTest passes the build tree's module): scikit-build configures
# python/CMakeLists.txt as usual and installs that file instead of compiling
# the binding files a second time (CRSPLINE_PY_PREBUILT there); the installed
# copy must then be byte for byte the one given.
foreach(var SOURCE_DIR WORK_DIR PYTHON)
    if(NOT DEFINED ${var})
        message(FATAL_ERROR "pass -D${var}=...")
    endif()
endforeach()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/src)
# What python/CMakeLists.txt needs standalone: the core project and python/.
file(COPY ${SOURCE_DIR}/CMakeLists.txt ${SOURCE_DIR}/cmake ${SOURCE_DIR}/include DESTINATION ${WORK_DIR}/src)
file(COPY ${SOURCE_DIR}/python DESTINATION ${WORK_DIR}/src
     PATTERN _skbuild EXCLUDE PATTERN *.egg-info EXCLUDE PATTERN __pycache__ EXCLUDE)

set(ENV{PYTHONPATH} "")
set(ENV{PYTHONDONTWRITEBYTECODE} 1)
set(ENV{PIP_NO_INDEX} 1)
set(ENV{PIP_DISABLE_PIP_VERSION_CHECK} 1)
set(ENV{CMAKE_BUILD_PARALLEL_LEVEL} 2)
if(DEFINED MODULE AND NOT MODULE STREQUAL "")
    if(NOT EXISTS ${MODULE})
        message(FATAL_ERROR "MODULE ${MODULE} does not exist")
    endif()
    set(ENV{SKBUILD_CONFIGURE_OPTIONS} "-DCRSPLINE_PY_PREBUILT=${MODULE}")
else()
    unset(ENV{SKBUILD_CONFIGURE_OPTIONS})
endif()

execute_process(COMMAND ${PYTHON} -m venv --system-site-packages ${WORK_DIR}/venv COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${WORK_DIR}/venv/bin/pip install --no-build-isolation --no-index ${WORK_DIR}/src/python
                WORKING_DIRECTORY ${WORK_DIR}
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pip install failed (${rc})")
endif()

# Import from the venv, from a folder with no crspline in it.
execute_process(
    COMMAND ${WORK_DIR}/venv/bin/python -c [=[
import sys, numpy as np, crspline
assert crspline.__file__.startswith(sys.prefix), (crspline.__file__, sys.prefix)
c = crspline.CatmullRom([[0, 0], [1, 2], [3, 2], [4, 0]])
assert np.array_equal(c.evaluate(c.grid), c.points)
print("installed", crspline.__version__, "at", crspline.__file__)
print("module", crspline._crspline.__file__)
]=]
    WORKING_DIRECTORY ${WORK_DIR}
    OUTPUT_VARIABLE import_out
    COMMAND_ERROR_IS_FATAL ANY)
message(STATUS "${import_out}")
if(DEFINED MODULE AND NOT MODULE STREQUAL "")
    string(REGEX MATCH "module ([^\n]+)" _ "${import_out}")
    set(installed ${CMAKE_MATCH_1})
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${MODULE} ${installed} RESULT_VARIABLE same)
    if(NOT same EQUAL 0)
        message(FATAL_ERROR "the installed module ${installed} is not the one given, ${MODULE}")
    endif()
endif()
