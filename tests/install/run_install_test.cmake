# Installs gecko into a fresh prefix and builds two consumers:
#   consumer/         find_package(gecko CONFIG REQUIRED) against that prefix
#   subdir_consumer/  add_subdirectory(<gecko source>)
# Run as: cmake -DSOURCE_DIR=... -DWORK_DIR=... -DCONSUMER_DIR=... -P run_install_test.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "command failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
endfunction()

run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/gecko-build -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX} -DGECKO_BUILD_TESTS=OFF -DCMAKE_INSTALL_PREFIX=${prefix})
run(${CMAKE_COMMAND} --install ${WORK_DIR}/gecko-build)
foreach(f include/gecko/gecko.hpp share/cmake/gecko/gecko-config.cmake
          share/cmake/gecko/gecko-config-version.cmake share/cmake/gecko/gecko-targets.cmake)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install is missing ${f}")
  endif()
endforeach()

# find_package consumer
run(${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/consumer-build -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer-build)
run(${WORK_DIR}/consumer-build/consumer)

# add_subdirectory consumer
run(${CMAKE_COMMAND} -S ${CONSUMER_DIR}/../subdir_consumer -B ${WORK_DIR}/subdir-build -G ${GENERATOR}
    -DCMAKE_CXX_COMPILER=${CXX} -DGECKO_SOURCE_DIR=${SOURCE_DIR})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/subdir-build)
run(${WORK_DIR}/subdir-build/consumer)
