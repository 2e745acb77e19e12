// An empty translation unit: the libraries vmodules and vstream_up5k hold only Verilated sources.
namespace {
[[maybe_unused]] void anchor() {}
}  // namespace
