// The browser side of the workstation's files (emcc --js-library): see ui/platform/files.hpp.
mergeInto(LibraryManager.library, {});
