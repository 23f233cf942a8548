// Knowledge-base YAML (coverkit.kb/1, multi_st's rules) → parseKnowledgeBase (the reader behind
// --param kb=FILE, without the file).
#include "fuzz_common.h"

#include <coverkit/planners/knowledge_base.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  coverkit::fuzz::expectReadOrInputError([&] { coverkit::planners::parseKnowledgeBase(text, "fuzz.yaml"); });
  return 0;
}
