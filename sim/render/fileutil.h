// fileutil.h - output files appear whole or not at all: write to "<path>.tmp", then rename.
#pragma once

#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "cli.h"

namespace spec {
namespace render {

// Calls write(tmp_path); on success renames tmp_path to path, on any exception removes tmp_path and
// rethrows. write() must throw std::runtime_error when it cannot write.
inline void write_atomic(const std::string& path, const std::function<void(const std::string&)>& write) {
    const std::string tmp = path + ".tmp";
    try {
        write(tmp);
        if (std::rename(tmp.c_str(), path.c_str()) != 0) throw InputError("cannot write " + path);
    } catch (...) {
        std::remove(tmp.c_str());
        throw;
    }
}

}  // namespace render
}  // namespace spec
