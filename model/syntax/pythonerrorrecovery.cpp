#include "syntax/pythonerrorrecovery.h"

#include "syntax/syntaxtree.h"

#include <cctype>

#include <vector>

namespace rosarch {

namespace {
struct Block
{
    qsizetype begin = 0; ///< byte offset of its first line
    qsizetype end = 0;   ///< byte offset after its last line
    int line = 1;        ///< 1-based first line
};

bool startsBlock(const QByteArray &line, bool afterDecorator)
{
    if (line.isEmpty() || afterDecorator)
        return false;
    const char c = line.at(0);
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '#' || c == ')' || c == ']' ||
        c == '}')
        return false;
    // clauses that continue the compound statement above them
    for (const char *clause : {"else", "elif", "except", "finally"}) {
        if (line.startsWith(clause)) {
            const qsizetype n = qsizetype(qstrlen(clause));
            if (line.size() == n || !(std::isalnum(uchar(line.at(n))) || line.at(n) == '_'))
                return false;
        }
    }
    return true;
}

/// Top-level blocks: a block starts at a line with code in column 0, outside triple-quoted
/// strings and not right after a decorator.
std::vector<Block> topLevelBlocks(const QByteArray &source)
{
    std::vector<Block> blocks;
    bool inString = false;
    bool afterDecorator = false;
    qsizetype pos = 0;
    int line = 1;
    while (pos < source.size()) {
        qsizetype eol = source.indexOf('\n', pos);
        const qsizetype next = eol < 0 ? source.size() : eol + 1;
        const QByteArray text = source.mid(pos, next - pos);
        if (!inString && startsBlock(text, afterDecorator)) {
            if (!blocks.empty())
                blocks.back().end = pos;
            blocks.push_back({pos, source.size(), line});
        }
        if (!inString && !text.trimmed().isEmpty() && !text.startsWith('#'))
            afterDecorator = text.startsWith('@');
        const int quotes = int(text.count("\"\"\"") + text.count("'''"));
        if (quotes % 2 == 1)
            inString = !inString;
        pos = next;
        ++line;
    }
    if (blocks.empty() || blocks.front().begin > 0)
        blocks.insert(blocks.begin(),
                      Block{0, blocks.empty() ? source.size() : blocks.front().begin, 1});
    return blocks;
}
} // namespace

QByteArray PythonErrorRecovery::isolate(const QByteArray &source, const QString &file,
                                        QList<Diagnostic> *diagnostics)
{
    QByteArray out = source;
    for (const Block &b : topLevelBlocks(source)) {
        const QByteArray text = source.mid(b.begin, b.end - b.begin);
        const SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Python, text, file);
        if (!ts::isNull(tree.root()) && !ts_node_has_error(tree.root()))
            continue;
        for (qsizetype i = b.begin; i < b.end; ++i)
            if (out.at(i) != '\n')
                out[i] = ' ';
        const int lastLine = b.line + int(text.trimmed().count('\n'));
        for (Diagnostic d : tree.syntaxErrors()) {
            d.evidence.line += b.line - 1;
            d.evidence.endLine += b.line - 1;
            d.message = QStringLiteral("Syntax error in %1 at line %2; lines %3-%4 were skipped, "
                                       "the rest of the file is still analysed.")
                            .arg(file)
                            .arg(d.evidence.line)
                            .arg(b.line)
                            .arg(lastLine);
            diagnostics->append(d);
        }
    }
    return out;
}

} // namespace rosarch
