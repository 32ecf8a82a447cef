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
                  include/lbmshape/core/error.hpp include/lbmshape/shaders/adaptive_gamma_bounds.h share/doc/lbmshape/LICENSE
                  lib/cmake/lbmshape/lbmshapeConfig.cmake lib/pkgconfig/lbmshape.pc
                  share/bash-completion/completions/lbmshape ${MAN_PAGE})
  if(NOT EXISTS ${prefix}/${installed})
    message(FATAL_ERROR "cmake --install left out ${installed}")
  endif()
endforeach()

# The installed headers are exactly those lbmshape.hpp reaches, and these
# reach nothing but the C and C++ standard libraries, GLM and nlohmann-json,
# the dependencies lbmshapeConfig.cmake and lbmshape.pc declare: no
# Vulkan-Hpp, tinygltf, OpenMesh or OpenMP for a program to find by chance.
file(WRITE ${WORK_DIR}/api.cpp "#include <lbmshape/lbmshape.hpp>\n")
run("listing what lbmshape.hpp includes" c++ -std=c++20 -M -I${prefix}/include ${WORK_DIR}/api.cpp)
string(REGEX REPLACE "[ \t\r\n\\]+" ";" reached "${output}")
set(reached_headers)
set(undeclared)
foreach(file IN LISTS reached)
  if(file STREQUAL "" OR file MATCHES ":$" OR file STREQUAL "${WORK_DIR}/api.cpp")
    continue()
  endif()
  if(file MATCHES "^${prefix}/include/lbmshape/(.*)$")
    list(APPEND reached_headers ${CMAKE_MATCH_1})
  elseif(file MATCHES "/(omp|tiny_gltf|stb_[^/]*|png|zlib)\\.h$")  # beside the C library's own
    list(APPEND undeclared ${file})
  elseif(NOT file MATCHES "/(glm|nlohmann)/"
         AND NOT file MATCHES "^/usr/(include/(c\\+\\+|[a-z0-9_]+-linux-gnu[a-z0-9_]*|linux|asm|asm-generic)/|lib/gcc/)"
         AND NOT file MATCHES "^/usr/include/[^/]+\\.h$")
    list(APPEND undeclared ${file})
  endif()
endforeach()
if(undeclared)
  message(FATAL_ERROR "the installed headers include what the package does not declare:\n${undeclared}")
endif()
file(GLOB_RECURSE installed_headers RELATIVE ${prefix}/include/lbmshape ${prefix}/include/lbmshape/*)
list(SORT reached_headers)
list(REMOVE_DUPLICATES reached_headers)
list(SORT installed_headers)
if(NOT reached_headers STREQUAL installed_headers)
  message(FATAL_ERROR "installed headers: ${installed_headers}\nlbmshape.hpp reaches: ${reached_headers}\n"
                      "(the list api_headers in cmake/install.cmake)")
endif()
list(LENGTH installed_headers header_count)
message(STATUS "${header_count} headers installed, all reached from lbmshape.hpp")

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
