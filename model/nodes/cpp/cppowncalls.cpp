#include "nodes/cpp/cppnameresolver.h"

#include "syntax/cppsyntax.h"

// What a method's parameter is given where the class calls the method itself.
namespace rosarch {

using namespace cppsyntax;

// `initializeFilter(filter_info_topic_)` in the class's own code, and only such calls: argument
// `index` of the method of `ctx`, when every call in the class's lineage passes the same
// expression (a member, usually). `caller` is where that argument is written.
const CppValue *CppNameResolver::ownCallArgument(int index, const CppLinkContext &ctx,
                                                 CppLinkContext *caller) const
{
    if (!ctx.fn || ctx.fn->isConstructor || ctx.cls < 0 || index < 0)
        return nullptr;
    const CppValue *found = nullptr;
    const int from = ctx.self >= 0 ? ctx.self : ctx.cls;
    for (int c : m_index.lineage(from)) {
        for (const auto &ref : m_index.at(c).functions) {
            for (const CppFreeCall &call : ref.function->freeCalls) {
                if (lastSegment(call.function) != ctx.fn->name || call.arguments.size() <= index)
                    continue;
                const CppValue &arg = call.arguments.at(index);
                if (ref.function == ctx.fn || (found && found->text != arg.text))
                    return nullptr; // recursive, or called with different values
                if (!found) {
                    found = &arg;
                    *caller = CppLinkContext{c, ref.function, ref.file, ctx.subst, ctx.self};
                }
            }
        }
    }
    return found;
}

} // namespace rosarch
