# Eigen 3.3 through 5.x are accepted, by gecko's own build and by the installed gecko-config.cmake;
# anything outside is refused with a message naming the version. The real Eigen found on the
# machine (e.g. Debian's 3.4) is used as is; Eigen 5 (not packaged everywhere yet), 3.2 and 6 are
# stood in for by a package config that reports that version and wraps the real headers, written
# the way Eigen writes its own (a SameMajorVersion version file).
# Run as: cmake -DSOURCE_DIR=... -DWORK_DIR=... -DCONSUMER_DIR=... -DGENERATOR=... -DCXX=...
#               -P eigen_versions.cmake
file(REMOVE_RECURSE ${WORK_DIR})

function(run expect_ok log)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expect_ok AND NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  elseif(NOT expect_ok AND rc EQUAL 0)
    message(FATAL_ERROR "command should have failed: ${ARGN}\n${out}")
  endif()
  set(${log} "${out}${err}" PARENT_SCOPE)
endfunction()

# The real Eigen: its include directory, from a throwaway project.
file(WRITE ${WORK_DIR}/probe/CMakeLists.txt [=[
cmake_minimum_required(VERSION 3.18)
project(probe NONE)
find_package(Eigen3 REQUIRED NO_MODULE)
get_target_property(inc Eigen3::Eigen INTERFACE_INCLUDE_DIRECTORIES)
file(WRITE ${CMAKE_BINARY_DIR}/eigen.txt "${Eigen3_VERSION};${inc}")
]=])
run(TRUE log ${CMAKE_COMMAND} -S ${WORK_DIR}/probe -B ${WORK_DIR}/probe/build)
file(READ ${WORK_DIR}/probe/build/eigen.txt probe)
list(GET probe 0 real_version)
list(GET probe 1 real_include)
message(STATUS "real Eigen ${real_version} at ${real_include}")

function(fake_eigen version dir)
  file(WRITE ${dir}/Eigen3Config.cmake "
if(NOT TARGET Eigen3::Eigen)
  add_library(Eigen3::Eigen INTERFACE IMPORTED)
  set_target_properties(Eigen3::Eigen PROPERTIES INTERFACE_INCLUDE_DIRECTORIES \"${real_include}\")
endif()
")
  include(CMakePackageConfigHelpers)
  write_basic_package_version_file(${dir}/Eigen3ConfigVersion.cmake VERSION ${version}
                                   COMPATIBILITY SameMajorVersion)
endfunction()

# gecko's build and an installed-gecko consumer against one Eigen (Eigen3_DIR empty: the real one).
function(check label eigen_dir expect_ok)
  set(w ${WORK_DIR}/${label})
  set(eigen_arg)
  if(eigen_dir)
    set(eigen_arg -DEigen3_DIR=${eigen_dir})
  endif()
  run(${expect_ok} log ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${w}/gecko-build -G ${GENERATOR}
      -DCMAKE_CXX_COMPILER=${CXX} -DGECKO_BUILD_TESTS=OFF -DGECKO_INSTALL=ON
      -DCMAKE_INSTALL_PREFIX=${w}/prefix ${eigen_arg})
  if(NOT expect_ok)
    if(NOT log MATCHES "gecko needs Eigen 3.3 through 5.x")
      message(FATAL_ERROR "${label}: refused without naming the allowed range:\n${log}")
    endif()
    message(STATUS "${label}: refused, as it should be")
    return()
  endif()
  run(TRUE log ${CMAKE_COMMAND} --install ${w}/gecko-build)
  run(TRUE log ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${w}/consumer-build -G ${GENERATOR}
      -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${w}/prefix ${eigen_arg})
  run(TRUE log ${CMAKE_COMMAND} --build ${w}/consumer-build)
  run(TRUE log ${w}/consumer-build/consumer)
  message(STATUS "${label}: gecko configures, installs, and a find_package consumer builds and runs")
endfunction()

check(eigen-real "" TRUE)
foreach(v 5.0.0 3.2.10 6.0.0)
  fake_eigen(${v} ${WORK_DIR}/fake-${v})
  if(v VERSION_LESS 3.3 OR NOT v VERSION_LESS 6)
    check(eigen-${v} ${WORK_DIR}/fake-${v} FALSE)
  else()
    check(eigen-${v} ${WORK_DIR}/fake-${v} TRUE)
  endif()
endforeach()

# The installed config refuses a wrong Eigen too (gecko installed with the real one, consumed with 6).
run(FALSE log ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/consumer-eigen6 -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${WORK_DIR}/eigen-real/prefix
    -DEigen3_DIR=${WORK_DIR}/fake-6.0.0)
if(NOT log MATCHES "gecko needs Eigen 3.3 through 5.x")
  message(FATAL_ERROR "installed config: refused Eigen 6 without naming the allowed range:\n${log}")
endif()
message(STATUS "installed gecko-config.cmake refuses Eigen 6, as it should")
