#pragma once

// A structure-aware mutator for the launch, build-file and workspace targets: the
// byte-level mutations never found values doubled in loops, includes multiplying includes or
// deep nesting, which take whole spans and references. Half of the mutations are these:
//  - span duplication: a span of the input inserted again right after itself;
//  - argument doubling: a reference (`$(var x)`, `${x}`, `LaunchConfiguration('x')`) written
//    twice in a row, so that a value built from it doubles;
//  - deep nesting: a span wrapped in a group, parentheses or brackets, many times;
// the other half are libFuzzer's own (LLVMFuzzerMutate).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>

extern "C" size_t LLVMFuzzerMutate(uint8_t *data, size_t size, size_t maxSize);

namespace rosarch::fuzz {

inline size_t structureMutate(uint8_t *data, size_t size, size_t maxSize, unsigned int seed)
{
    std::minstd_rand rng(seed);
    if (size == 0 || rng() % 2 == 0)
        return LLVMFuzzerMutate(data, size, maxSize);
    std::string s(reinterpret_cast<const char *>(data), size);
    const size_t keep = std::min<size_t>(1, s.size()); // the first byte picks a reader
    auto pick = [&](size_t n) { return n == 0 ? 0 : size_t(rng() % n); };
    switch (rng() % 3) {
    case 0: { // span duplication
        const size_t from = keep + pick(s.size() - keep);
        const size_t length = 1 + pick(std::min<size_t>(s.size() - from, 256));
        s.insert(from + length, s.substr(from, length));
        break;
    }
    case 1: { // argument doubling
        static const char *openers[] = {"$(var ", "${", "LaunchConfiguration(", "$(env "};
        const char *open = openers[pick(4)];
        const size_t at = s.find(open, keep + pick(s.size() - keep));
        const size_t found = at == std::string::npos ? s.find(open) : at;
        if (found == std::string::npos || found < keep)
            return LLVMFuzzerMutate(data, size, maxSize);
        const char close = open[std::strlen(open) - 1] == '{' ? '}' : ')';
        const size_t end = s.find(close, found);
        if (end == std::string::npos)
            return LLVMFuzzerMutate(data, size, maxSize);
        s.insert(end + 1, s.substr(found, end + 1 - found));
        break;
    }
    default: { // deep nesting
        static const char *pairs[][2] = {{"<group>", "</group>"},
                                         {"(", ")"},
                                         {"[", "]"},
                                         {"{", "}"},
                                         {"if(A)\n", "\nendif()\n"}};
        const auto &pair = pairs[pick(5)];
        const size_t from = keep + pick(s.size() - keep);
        const size_t to = from + pick(s.size() - from + 1);
        const int depth = 1 + int(pick(64));
        std::string open, close;
        for (int i = 0; i < depth; ++i) {
            open += pair[0];
            close += pair[1];
        }
        s.insert(to, close);
        s.insert(from, open);
        break;
    }
    }
    const size_t n = std::min(s.size(), maxSize);
    std::memcpy(data, s.data(), n);
    return n;
}

} // namespace rosarch::fuzz

/// Defines the target's custom mutator as the structure-aware one.
#define ROSARCH_STRUCTURE_MUTATOR                                                                  \
    extern "C" size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t maxSize,          \
                                              unsigned int seed)                                   \
    {                                                                                              \
        return rosarch::fuzz::structureMutate(data, size, maxSize, seed);                          \
    }
