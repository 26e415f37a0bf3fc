# Cross-building for 64-bit ARM with Debian's cross toolchain (crossbuild-essential-arm64) and
# multi-arch arm64 development packages (scripts/build_aarch64.sh). Test programs run under
# qemu-user, with the arm64 libraries' root for the dynamic loader.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64;-L;/usr/aarch64-linux-gnu)
