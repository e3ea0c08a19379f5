#include "syntax/parsehandoff.h"

#include "syntax/pythonsyntax.h"

#include <QHash>

#include <mutex>

namespace rosarch {

namespace {

/// What waits to be taken may hold this many bytes of source (a tree takes several times as
/// much): a workspace of huge launch files parses them twice rather than hold them all.
constexpr qsizetype kMaxWaitingBytes = qsizetype(32) << 20;

struct Waiting
{
    std::mutex mutex;
    bool open = false;
    qsizetype bytes = 0;
    QHash<QString, std::shared_ptr<SyntaxTree>> trees; // by file
};

Waiting &handoff()
{
    static Waiting w;
    return w;
}

} // namespace

ParseHandoff::Run::Run()
{
    Waiting &w = handoff();
    const std::lock_guard lock(w.mutex);
    if (w.open)
        return;
    w.open = true;
    m_owner = true;
}

ParseHandoff::Run::~Run()
{
    if (!m_owner)
        return;
    QHash<QString, std::shared_ptr<SyntaxTree>> dropped;
    Waiting &w = handoff();
    {
        const std::lock_guard lock(w.mutex);
        w.open = false;
        w.bytes = 0;
        dropped.swap(w.trees);
    }
    // the trees are freed here, outside the lock
}

bool ParseHandoff::wanted(const QByteArray &content)
{
    return py::namesLaunchFunction(content);
}

std::optional<SyntaxTree> ParseHandoff::take(const QString &file, const QByteArray &content)
{
    std::shared_ptr<SyntaxTree> tree;
    {
        Waiting &w = handoff();
        const std::lock_guard lock(w.mutex);
        tree = w.trees.take(file);
        if (tree)
            w.bytes -= tree->source().size();
    }
    // Another version of the file (changed between the two reads) is not this one's tree.
    if (!tree || tree->source() != content)
        return std::nullopt;
    return std::move(*tree);
}

SyntaxTree ParseHandoff::takeOrParse(const QString &file, const QByteArray &content,
                                     bool *parsedHere)
{
    std::optional<SyntaxTree> taken = take(file, content);
    *parsedHere = !taken;
    return taken ? std::move(*taken)
                 : SyntaxTree::parse(SyntaxTree::Grammar::Python, content, file);
}

void ParseHandoff::offer(SyntaxTree tree)
{
    if (tree.file().isEmpty() || ts::isNull(tree.root()))
        return;
    auto shared = std::make_shared<SyntaxTree>(std::move(tree));
    Waiting &w = handoff();
    const std::lock_guard lock(w.mutex);
    const qsizetype size = shared->source().size();
    if (!w.open || w.trees.contains(shared->file()) || w.bytes + size > kMaxWaitingBytes)
        return; // freed after the lock is released: `shared` was made before it
    w.bytes += size;
    w.trees.insert(shared->file(), shared);
}

int ParseHandoff::waitingCount()
{
    Waiting &w = handoff();
    const std::lock_guard lock(w.mutex);
    return int(w.trees.size());
}

} // namespace rosarch
