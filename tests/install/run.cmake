# cmake -DBUILD_DIR=... -DCONSUMER_DIR=... -DWORK_DIR=... -DCXX=... -DWITH_MESA=ON|OFF -P run.cmake
# Installs the build into WORK_DIR/prefix, then builds tests/install/consumer against it twice,
# with find_package(ffcompat) and with pkg-config, and runs both (consumer.cpp checks a lit pixel).
cmake_minimum_required(VERSION 3.20)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

set(backends soft)
if(WITH_MESA)
  list(APPEND backends mesa)
endif()

# find_package
run(${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/cmake -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/cmake -j2)
run(${WORK_DIR}/cmake/consumer ${backends})
message(STATUS "find_package consumer:\n${out}")

# pkg-config (the libraries are static: --static for the full link line)
run(${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${prefix}/lib/pkgconfig pkg-config --static --cflags --libs ffcompat)
string(STRIP "${out}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
run(${CXX} -std=c++17 -O2 ${CONSUMER_DIR}/consumer.cpp ${flags} -o ${WORK_DIR}/pc-consumer)
run(${WORK_DIR}/pc-consumer ${backends})
message(STATUS "pkg-config consumer (${flags}):\n${out}")

# Without Mesa (no OSMesa, no EGL), asking for "mesa" names why it is missing.
if(NOT WITH_MESA)
  execute_process(COMMAND ${WORK_DIR}/pc-consumer mesa RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc EQUAL 0 OR NOT out MATCHES "backend 'mesa' is not built: neither OSMesa nor EGL was found at configure time")
    message(FATAL_ERROR "a mesa context without OSMesa should fail naming why; got (${rc}):\n${out}")
  endif()
  message(STATUS "without OSMesa:\n${out}")
endif()
