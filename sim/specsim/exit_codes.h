// exit_codes.h - what specsim's exit code says (main.cpp; tested in tests/test_specsim.cpp):
//   0  success
//   2  bad input: spec::UsageError (the command line) or spec::InputError (a file, an output path) - one line
//      on stderr, "specsim: <what is wrong>"
//   3  an internal error: any other exception - "specsim: internal error: <what>". A bug (or a broken
//      installation, e.g. gnuplot missing), never the user's input; fuzz_specsim fails on it.
#pragma once

#include <exception>
#include <functional>
#include <ostream>

#include "cli.h"

namespace spec {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 3;

// Runs the command and turns what escapes it into the exit code, with its one line on err.
inline int exit_code_of(const std::function<int()>& command, std::ostream& err) {
    try {
        return command();
    } catch (const UsageError& e) {
        err << "specsim: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const InputError& e) {
        err << "specsim: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        err << "specsim: internal error: " << printable(e.what()) << "\n";
        return kExitInternal;
    } catch (...) {
        err << "specsim: internal error: an exception that is not a std::exception\n";
        return kExitInternal;
    }
}

}  // namespace spec
