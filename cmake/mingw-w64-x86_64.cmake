# Cross-compiles for 64-bit Windows with mingw-w64 (Debian: gcc-mingw-w64-x86-64):
#   cmake -S . -B build-windows -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64-x86_64.cmake
# builds usrsub.dll (docs/windows.md).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)

set(USRSUB_MINGW_PREFIX x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${USRSUB_MINGW_PREFIX}-gcc)
set(CMAKE_RC_COMPILER ${USRSUB_MINGW_PREFIX}-windres)
set(CMAKE_DLLTOOL ${USRSUB_MINGW_PREFIX}-dlltool)
set(CMAKE_OBJDUMP ${USRSUB_MINGW_PREFIX}-objdump)

# Headers and libraries from the target's root only; programs from the host.
set(CMAKE_FIND_ROOT_PATH /usr/${USRSUB_MINGW_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
