// Runs many CLI cases in one process (tests only): the hostile-input and fuzz suites on the WASM and
// sanitized builds, where starting a process costs more than the case (0.3 CPU s to compile niwa.js
// under node, 0.12-0.18 s to start the ASan binary).
//
// Usage: niwa_cli_batch [--stdout] CASES
// CASES holds the cases back to back, each "<index> <argc>\n" then per argument "<bytes>\n<arg>\n"
// (arguments may hold any byte but NUL, newlines included). For each case it calls RunCli, the same
// entry point as the niwa executable's main, with stdout discarded and stderr (its stream and
// std::cerr, which a few warnings write to directly) captured, and prints one line on stdout:
// "<index> <exit code> <stderr as a JSON string>", flushed, so a reader can time each case and tell
// which one crashed or hung (the one after the last line). With --stdout the line keeps the case's
// stdout too: "<index> <exit code> [<stderr>,<stdout>]" (a JSON array of two strings), for the
// native-against-WASM tests that compare what a run prints (tests/cli/moss_cli.test.mjs).
//
// What it does not do: isolate cases from each other (a case that corrupts memory or hangs ends the
// batch: the reader restarts it after that case), or run a case with a fresh process's globals
// (RunCli rebuilds its flags per call; core caches are keyed by their inputs).
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli.h"
#include "process_heap.h"

namespace {

std::string JsonString(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7f) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", u);
      out += esc;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

bool ReadCase(std::istream& in, long* index, std::vector<std::string>* args) {
  std::size_t argc = 0;
  if (!(in >> *index >> argc) || in.get() != '\n') return false;
  args->assign(argc, std::string());
  for (std::string& arg : *args) {
    std::size_t bytes = 0;
    if (!(in >> bytes) || in.get() != '\n') return false;
    arg.resize(bytes);
    if (bytes > 0 && !in.read(arg.data(), static_cast<std::streamsize>(bytes))) return false;
    if (in.get() != '\n') return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const bool keep_stdout = argc == 3 && std::string(argv[1]) == "--stdout";
  if (argc != 2 && !keep_stdout) {
    std::fprintf(stderr, "usage: niwa_cli_batch [--stdout] CASES\n");
    return 2;
  }
  niwa::KeepFreedMemoryForReuse();
  const char* const cases = argv[argc - 1];
  std::ifstream in(cases, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "niwa_cli_batch: cannot read %s\n", cases);
    return 2;
  }
  std::streambuf* const real_cout = std::cout.rdbuf();
  std::streambuf* const real_cerr = std::cerr.rdbuf();
  std::ostream report(real_cout);
  long index = 0;
  std::vector<std::string> args;
  int ran = 0;
  while (in.peek() != EOF) {
    if (!ReadCase(in, &index, &args)) {
      std::fprintf(stderr, "niwa_cli_batch: malformed case after %d cases\n", ran);
      return 2;
    }
    std::ostringstream out;
    std::ostringstream err;
    std::cout.rdbuf(out.rdbuf());
    std::cerr.rdbuf(err.rdbuf());
    const int code = niwa::RunCli(args, out, err);
    std::cout.rdbuf(real_cout);
    std::cerr.rdbuf(real_cerr);
    if (keep_stdout) {
      report << index << ' ' << code << " [" << JsonString(err.str()) << ','
             << JsonString(out.str()) << ']' << std::endl;
    } else {
      report << index << ' ' << code << ' ' << JsonString(err.str()) << std::endl;
    }
    ++ran;
  }
  return 0;
}
