# CMake generated Testfile for 
# Source directory: /work/main/legacy_examples
# Build directory: /work/main/build-examples/legacy_examples
# 
# This file includes the relevant testing commands required for 
# testing this directory and lists subdirectories to be tested as well.
