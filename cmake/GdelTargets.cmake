# Helpers that give every gdel target the same flags.
#
# gdel_configure_target(<target>) sets include paths, the no-contraction flags, the
# Thrust system per language (host TUs use the OpenMP device system: the CPU backend;
# .cu TUs keep the CUDA system: the CUDA backend) and OpenMP.
function(gdel_configure_target tgt)
  target_include_directories(${tgt} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
    $<INSTALL_INTERFACE:include>)
  target_include_directories(${tgt} SYSTEM PUBLIC $<BUILD_INTERFACE:${GDEL_CCCL_INCLUDE}> $<BUILD_INTERFACE:${GDEL_CCCL_PARENT}>)
  target_compile_options(${tgt} PRIVATE
    $<$<COMPILE_LANGUAGE:CXX>:${GDEL_HOST_FLAGS} -Wall -Wextra -Wno-unknown-pragmas>
    $<$<COMPILE_LANGUAGE:CUDA>:--fmad=false --extended-lambda --expt-relaxed-constexpr -Xcompiler=-ffp-contract=off,-fopenmp -Xcudafe=--diag_suppress=esa_on_defaulted_function_ignored>
    $<$<AND:$<COMPILE_LANGUAGE:CUDA>,$<NOT:$<STREQUAL:${GDEL_CUDA_SPLIT_COMPILE},1>>>:--split-compile=${GDEL_CUDA_SPLIT_COMPILE}>)
  target_compile_definitions(${tgt} PRIVATE
    $<$<COMPILE_LANGUAGE:CXX>:THRUST_DEVICE_SYSTEM=THRUST_DEVICE_SYSTEM_OMP>
    $<$<COMPILE_LANGUAGE:CUDA>:GDEL_CUDA_TU=1>)
  target_link_libraries(${tgt} PUBLIC OpenMP::OpenMP_CXX)
  if(GDEL_HAVE_CUDA)
    target_compile_definitions(${tgt} PUBLIC GDEL_HAVE_CUDA=1)
    set_target_properties(${tgt} PROPERTIES CUDA_SEPARABLE_COMPILATION OFF)
  endif()
  if(GDEL_SANITIZE)
    target_compile_options(${tgt} PRIVATE $<$<COMPILE_LANGUAGE:CXX>:-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -fsanitize-recover=null>)
    target_link_options(${tgt} PUBLIC -fsanitize=address,undefined)
  endif()
endfunction()

# gdel_link_cgal(<target> <PUBLIC|PRIVATE>): CGAL, with TBB for Parallel_tag when found
# (defines CGAL_LINKED_WITH_TBB).
function(gdel_link_cgal tgt scope)
  target_link_libraries(${tgt} ${scope} CGAL::CGAL)
  find_package(TBB QUIET)
  if(TBB_FOUND)
    include(CGAL_TBB_support OPTIONAL)
  endif()
  if(TARGET CGAL::TBB_support)
    target_link_libraries(${tgt} ${scope} CGAL::TBB_support)
  elseif(TARGET TBB::tbb)
    target_link_libraries(${tgt} ${scope} TBB::tbb)
    target_compile_definitions(${tgt} ${scope} CGAL_LINKED_WITH_TBB)
  endif()
endfunction()
