# The optional CUDA path (issue 7, item 5): the truncation-error kernel and the
# matrix-free Laplacian on an NVIDIA GPU, plus the bench_cuda program.  OFF by default;
# `make test` and `make report` never need it.
#
# Included at the END of the top-level CMakeLists.txt (after gpm_core exists):
#   include(cmake/cuda.cmake)
# Configure with
#   cmake -S . -B build-cuda -DCMAKE_BUILD_TYPE=Release -DGPM_CUDA=ON
# Before that line is in CMakeLists.txt, the same works by injection right after project():
#   cmake ... -DGPM_CUDA=ON -DCMAKE_PROJECT_INCLUDE=$PWD/cmake/cuda.cmake
# (bench/run_cuda_check.sh picks whichever applies; include_guard makes both harmless).
# nvcc is looked for on PATH, then at /usr/local/cuda/bin/nvcc; elsewhere pass
# -DCMAKE_CUDA_COMPILER=/path/to/nvcc.  The GPU generations default to 80;90 (A100,
# H100/H200); override with -DCMAKE_CUDA_ARCHITECTURES=...
#
# Sources: src/cuda/*.cu and src/cuda/*.cpp except bench_cuda.cpp form the library
# gpm_cuda; src/cuda/bench_cuda.cpp is the benchmark.  Nothing in src/cuda/ is matched by
# the default build's globs (src/gpm, src/apps, bench).
include_guard(GLOBAL)
option(GPM_CUDA "Build the optional CUDA path (src/cuda: gpm_cuda, bench_cuda)" OFF)

if(GPM_CUDA)
  include(CheckLanguage)
  if(NOT CMAKE_CUDA_COMPILER)
    find_program(GPM_NVCC nvcc HINTS /usr/local/cuda/bin)
    if(GPM_NVCC)
      set(CMAKE_CUDA_COMPILER "${GPM_NVCC}" CACHE FILEPATH "CUDA compiler")
    endif()
  endif()
  check_language(CUDA)
  if(NOT CMAKE_CUDA_COMPILER)
    message(FATAL_ERROR "GPM_CUDA=ON but no CUDA compiler was found: install the CUDA "
                        "toolkit or pass -DCMAKE_CUDA_COMPILER=/path/to/nvcc")
  endif()
  if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
    set(CMAKE_CUDA_ARCHITECTURES 80 90)
  endif()
  enable_language(CUDA)
  find_package(CUDAToolkit REQUIRED)

  file(GLOB GPM_CUDA_SOURCES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/cuda/*.cu
    ${CMAKE_SOURCE_DIR}/src/cuda/*.cpp)
  list(FILTER GPM_CUDA_SOURCES EXCLUDE REGEX "bench_cuda\\.cpp$")
  add_library(gpm_cuda STATIC ${GPM_CUDA_SOURCES})
  # The top level's add_compile_options (-Wall -Wextra -fno-math-errno -march=native) are
  # host-compiler flags that nvcc rejects: keep them for C++ sources only and give nvcc the
  # warnings through its host compiler, all warnings as errors.  From gpm_core (LINK_ONLY)
  # only its include paths and definitions reach the nvcc command line (checked with
  # VERBOSE=1); its dependencies' options (-fopenmp, -frounding-math) do not.
  get_target_property(GPM_CUDA_OPTS gpm_cuda COMPILE_OPTIONS)
  set(GPM_CUDA_CXX_OPTS)
  if(GPM_CUDA_OPTS)
    foreach(o ${GPM_CUDA_OPTS})
      list(APPEND GPM_CUDA_CXX_OPTS "$<$<COMPILE_LANGUAGE:CXX>:${o}>")
    endforeach()
  endif()
  set_target_properties(gpm_cuda PROPERTIES COMPILE_OPTIONS "${GPM_CUDA_CXX_OPTS}")
  target_compile_options(gpm_cuda PRIVATE
    $<$<COMPILE_LANGUAGE:CUDA>:-Xcompiler=-Wall,-Wextra --Werror=all-warnings>)
  # C++20 like the rest (the gpm headers may use it).  CMake 3.25 knows no CUDA20 dialect
  # flag for nvcc (nvcc 12+ accepts -std=c++20), so it is told; without a CUDA_STANDARD,
  # CMake falls back to CXX_STANDARD 20 and stops at generation.
  if(NOT DEFINED CMAKE_CUDA20_STANDARD_COMPILE_OPTION)
    set(CMAKE_CUDA20_STANDARD_COMPILE_OPTION "-std=c++20")
    set(CMAKE_CUDA20_EXTENSION_COMPILE_OPTION "-std=c++20")
  endif()
  set_target_properties(gpm_cuda PROPERTIES CUDA_STANDARD 20 CUDA_STANDARD_REQUIRED ON)
  target_include_directories(gpm_cuda PUBLIC ${CMAKE_SOURCE_DIR}/src)
  target_link_libraries(gpm_cuda PUBLIC $<LINK_ONLY:gpm_core> CUDA::cudart_static)

  # Every study program and the gpm tool get the device (src/cuda/device_install.cpp installs
  # it at start-up, so the library is linked whole); --device cuda selects it.
  foreach(app_src ${GPM_APPS})
    get_filename_component(app ${app_src} NAME_WE)
    if(TARGET ${app})
      target_link_libraries(${app} PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,gpm_cuda>")
    endif()
  endforeach()
  if(TARGET gpm)
    target_link_libraries(gpm PRIVATE "$<LINK_LIBRARY:WHOLE_ARCHIVE,gpm_cuda>")
  endif()

  add_executable(bench_cuda ${CMAKE_SOURCE_DIR}/src/cuda/bench_cuda.cpp)
  # C++20 stated here too: through CMAKE_PROJECT_INCLUDE (below) this file runs before the
  # top level sets CMAKE_CXX_STANDARD.
  set_target_properties(bench_cuda PROPERTIES CXX_STANDARD 20 CXX_STANDARD_REQUIRED ON)
  target_link_libraries(bench_cuda PRIVATE gpm_cuda gpm_core)
endif()
