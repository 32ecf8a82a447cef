# What a program outside the project sees: `cmake --install` into a fresh
# prefix, examples/denoise_in_memory configured against it with
# find_package(lbmshape), built and run, and the same source compiled with
# the flags `pkg-config lbmshape` gives, and (with -DPYTHON=interpreter) the
# Python module's tests on the installed module. Each step's failure fails the test
# with its output. Run by CTest (tests/CMakeLists.txt) as
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P check_install.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${code}):\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(installed bin/lbmshape lib/liblbmshape.so include/lbmshape/lbmshape.hpp include/lbmshape/version.hpp
                  include/lbmshape/core/error.hpp include/lbmshape/shaders/band_interface.h share/doc/lbmshape/LICENSE
                  lib/cmake/lbmshape/lbmshapeConfig.cmake lib/pkgconfig/lbmshape.pc
                  share/bash-completion/completions/lbmshape ${MAN_PAGE})
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "cmake --install left out ${installed}")
  endif()
endforeach()

run("configuring the example" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/denoise_in_memory -B ${WORK_DIR}/example
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release)
run("building the example" ${CMAKE_COMMAND} --build ${WORK_DIR}/example)
run("running the example" ${WORK_DIR}/example/denoise_in_memory --res 32)
if(NOT output MATCHES "lbmshape [0-9.]+ on .*farthest from the sphere")
  message(FATAL_ERROR "the example printed: ${output}")
endif()
message(STATUS "find_package(lbmshape): ${output}")

# pkg-config on a copy of the prefix elsewhere (a package's staging tree, a
# moved install): its flags name the copy.
find_program(PKG_CONFIG pkg-config REQUIRED)
set(moved ${WORK_DIR}/moved)
file(COPY ${prefix}/ DESTINATION ${moved})
set(ENV{PKG_CONFIG_PATH} ${moved}/lib/pkgconfig)
run("pkg-config lbmshape" ${PKG_CONFIG} --cflags --libs lbmshape)
if(NOT output MATCHES "-I${moved}/" OR NOT output MATCHES "-L${moved}/" OR output MATCHES "${prefix}")
  message(FATAL_ERROR "pkg-config on the copied prefix ${moved} gave: ${output}")
endif()
separate_arguments(flags UNIX_COMMAND "${output}")
# A program's own headers of the same names as the library's (a core/ or
# mesh/ folder of its own) come first on its include path: the library's
# headers, which include each other as "lbmshape/...", never reach them.
file(GLOB_RECURSE library_headers RELATIVE ${prefix}/include/lbmshape ${prefix}/include/lbmshape/*.hpp
     ${prefix}/include/lbmshape/*.h)
foreach(header IN LISTS library_headers)
  file(WRITE ${WORK_DIR}/programs_own_headers/${header} "#error the program's own ${header} was included\n")
endforeach()
run("compiling with pkg-config's flags" c++ -O1 ${SOURCE_DIR}/examples/denoise_in_memory/main.cpp
    -I${WORK_DIR}/programs_own_headers ${flags} -Wl,-rpath,${moved}/lib -o ${WORK_DIR}/denoise_with_pkg_config)
run("running what pkg-config built" ${WORK_DIR}/denoise_with_pkg_config --res 32)
message(STATUS "pkg-config lbmshape: ${output}")

if(PYTHON)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_DIR})
  run("the Python module's tests on the installed module" ${PYTHON} -m unittest discover -s ${SOURCE_DIR}/python/tests)
  run("finding the installed module" ${PYTHON} -c "print(__import__('lbmshape').__file__)")
  if(NOT output MATCHES "^${prefix}/")
    message(FATAL_ERROR "Python imported lbmshape from ${output}, not from the prefix")
  endif()
  message(STATUS "Python: lbmshape from ${output}")
endif()
