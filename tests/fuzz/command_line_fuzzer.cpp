// Fuzz target: the `lightlab` command line. The input is split at newlines into
// arguments and parsed by the real app (cli/command_line.h) without running the
// command; every "name=value" argument is also applied to the parameters of
// every technique and accelerator, as --set does. Only CLI11's ParseError and
// UserError may come out.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "cli/command_line.h"
#include "core/error.h"
#include "modules/registry.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> args;
  for (size_t begin = 0; begin <= input.size();) {
    const size_t end = std::min(input.find('\n', begin), input.size());
    args.push_back(input.substr(begin, end - begin));
    begin = end + 1;
  }
  if (args.size() > 64) return 0;  // long argument lists only repeat what short ones test
  {
    ll::cli::CommandLine cl;
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last-first
    try {
      cl.app.parse(reversed);
    } catch (const CLI::ParseError&) {
    }
  }
  for (const std::string& a : args) {
    if (a.find('=') == std::string::npos) continue;
    for (const ll::TechniqueInfo& t : ll::techniques()) {
      ll::ParamSet p(t.name, t.params);
      try {
        p.assign(a);
      } catch (const ll::UserError&) {
      }
    }
    for (const ll::AcceleratorInfo& acc : ll::accelerators()) {
      ll::ParamSet p(acc.name, acc.params);
      try {
        p.assign(a);
      } catch (const ll::UserError&) {
      }
    }
  }
  return 0;
}
