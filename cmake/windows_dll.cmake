# usrsub.dll, built with the mingw-w64 toolchain (docs/windows.md).
#
# Imports. The utilities host.c calls (c_sysary, c_errmes, ...) cannot stay
# undefined as in libusrsub.so: a DLL names the DLL each import comes from.
# They come from the solver's utility library, which MotionSolve's
# documentation recommends linking user subroutines against ("asutility",
# docs/sources.md M14); the import library is made from
# usrsub/entries/host_utilities.def for the DLL this option names.
set(USRSUB_UTILITY_DLL "asutility.dll" CACHE STRING
    "The solver's utility DLL that usrsub.dll imports c_sysary, c_errmes, ... from")
if(NOT CMAKE_DLLTOOL)
  find_program(CMAKE_DLLTOOL NAMES x86_64-w64-mingw32-dlltool dlltool REQUIRED)
endif()
set(USRSUB_UTILITY_DEF ${PROJECT_SOURCE_DIR}/usrsub/entries/host_utilities.def)
set(USRSUB_UTILITY_IMPORTS ${CMAKE_BINARY_DIR}/host_utilities.imports.a)
add_custom_command(OUTPUT ${USRSUB_UTILITY_IMPORTS}
  COMMAND ${CMAKE_DLLTOOL} --input-def ${USRSUB_UTILITY_DEF} --dllname ${USRSUB_UTILITY_DLL}
          --output-lib ${USRSUB_UTILITY_IMPORTS}
  DEPENDS ${USRSUB_UTILITY_DEF}
  COMMENT "Import library of ${USRSUB_UTILITY_DLL}" VERBATIM)
add_custom_target(host_utility_imports DEPENDS ${USRSUB_UTILITY_IMPORTS})
add_dependencies(usrsub host_utility_imports)
target_link_libraries(usrsub PRIVATE ${USRSUB_UTILITY_IMPORTS})

# Exports: the entries, each under both names, and nothing else: solver_abi.h
# marks them __declspec(dllexport), and the linker exports no other symbol
# once any is marked. The name a model gives: usrsub.dll, no "lib".
# libgcc is linked in, so the DLL needs nothing beside it but the utility DLL
# and Windows' own (tests/windows/check_dll.sh checks both lists).
set_target_properties(usrsub PROPERTIES PREFIX "")
target_link_options(usrsub PRIVATE -static-libgcc)

# The test host and the stand-in utility DLL that scripts/windows.sh runs
# under Wine (tests/windows/).
if(USRSUB_TESTS)
  add_subdirectory(tests/windows)
endif()
