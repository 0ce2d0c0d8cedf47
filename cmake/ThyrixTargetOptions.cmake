# Options applied target by target to Thyrix's own code, never globally, so that nothing leaks
# into a project that consumes Thyrix.
function(thyrix_target_options target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                             -Wno-sign-conversion)
    # No multiply-add fused where the compiler chooses (GCC does by default once the target
    # has FMA, e.g. -march=native): the hand-written vector paths (the articulated chain's SSE2
    # pairs) then keep the bits of their scalar twins, which the compiler would fuse otherwise.
    target_compile_options(${target} PRIVATE -ffp-contract=off)
    if(THYRIX_WARNINGS_AS_ERRORS)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
    if(THYRIX_SANITIZE)
      target_compile_options(${target} PRIVATE -fsanitize=${THYRIX_SANITIZE} -fno-omit-frame-pointer
                                               -fno-sanitize-recover=all)
      target_link_options(${target} PRIVATE -fsanitize=${THYRIX_SANITIZE})
    endif()
    if(THYRIX_BUILD_FUZZERS)  # coverage for libFuzzer; the fuzzers link its main themselves
      target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
    endif()
  elseif(MSVC)
    target_compile_options(${target} PRIVATE /W4 $<$<BOOL:${THYRIX_WARNINGS_AS_ERRORS}>:/WX>)
  endif()
endfunction()

# A library of Thyrix: alias thyrix::<export name>, headers installed under include/<folder>.
function(thyrix_add_library target export_name)
  cmake_parse_arguments(ARG "" "" "SOURCES;HEADERS;DEPENDS" ${ARGN})
  add_library(${target} ${ARG_SOURCES} ${ARG_HEADERS})
  add_library(thyrix::${export_name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name}
                                             OUTPUT_NAME thyrix${export_name})
  thyrix_target_options(${target})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                              $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>
                                              $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  if(ARG_DEPENDS)
    target_link_libraries(${target} PUBLIC ${ARG_DEPENDS})
  endif()
  get_filename_component(folder ${CMAKE_CURRENT_SOURCE_DIR} NAME)
  install(TARGETS ${target} EXPORT ThyrixTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(FILES ${ARG_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${folder})
endfunction()
