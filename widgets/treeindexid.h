#pragma once

#include <QModelIndex>
#include <QtGlobal>

#include <limits>
#include <type_traits>

namespace rosarch {

/// The QModelIndex::internalId of a row in a tree model: a tag (what the row is) in the low
/// `TagBits` bits and a payload (which row, or where its parent is) above it. A payload may be
/// read as two parts: a high part above the low `LowBits` bits.
///
/// An item model stores no pointer in its indexes (its rows are rebuilt on every change), so
/// a row must say in one quintptr what it is and how to find its parent again. This is the one
/// place that packs and unpacks that word: the models name tags and payloads, never bits.
///
/// quintptr has 32 bits on a 32-bit platform, so a payload has only 32 - TagBits bits there.
/// The constructors assert that what they pack fits; a model checks fits() first wherever a
/// payload can grow with the workspace, and shows no row it cannot name.
template <typename Tag, int TagBits, int LowBits = 0> class TreeIndexId
{
    static_assert(std::is_enum_v<Tag>, "a tag is an enumeration of the kinds of row");
    static_assert(TagBits >= 1 && TagBits <= 4, "a tag is a few bits");
    // What is left above the tag and the low part numbers the rows of a large workspace; a
    // model whose low part suits 64 bits chooses a narrower one where quintptr has 32.
    static_assert(LowBits >= 0 && TagBits + LowBits <= std::numeric_limits<quintptr>::digits - 16,
                  "the high part of a payload keeps at least 16 bits");

public:
    /// The bits of an internal id: 64, or 32 on a 32-bit platform.
    static constexpr int kIdBits = std::numeric_limits<quintptr>::digits;
    static constexpr int kPayloadBits = kIdBits - TagBits;
    static constexpr int kHighBits = kPayloadBits - LowBits;
    static constexpr quintptr kMaxTag = (quintptr(1) << TagBits) - 1;
    /// The largest payload; a qsizetype, so a row number or a negative one compares as it is.
    static constexpr qsizetype kMaxPayload = qsizetype(~quintptr(0) >> TagBits);
    static constexpr qsizetype kMaxHigh = kMaxPayload >> LowBits;
    static constexpr qsizetype kMaxLow = (qsizetype(1) << LowBits) - 1;

    /// Tag 0 and payload 0.
    constexpr TreeIndexId() = default;
    constexpr explicit TreeIndexId(Tag tag, qsizetype payload = 0)
        : m_id((quintptr(payload) << TagBits) | quintptr(tag))
    {
        Q_ASSERT(holds(tag));
        Q_ASSERT(fits(payload));
    }
    /// A payload of two parts: `high` above the `LowBits` bits of `low`.
    static constexpr TreeIndexId split(Tag tag, qsizetype high, qsizetype low)
    {
        Q_ASSERT(fits(high, low));
        return TreeIndexId(tag, (high << LowBits) | low);
    }
    /// The id a model stored with createIndex, read back.
    static constexpr TreeIndexId fromInternalId(quintptr id)
    {
        TreeIndexId out;
        out.m_id = id;
        return out;
    }
    static TreeIndexId of(const QModelIndex &index) { return fromInternalId(index.internalId()); }

    /// Whether `tag` has a value the tag bits can hold.
    static constexpr bool holds(Tag tag)
    {
        const auto value = qint64(tag);
        return value >= 0 && quint64(value) <= quint64(kMaxTag);
    }
    /// Whether `payload` can be packed: not negative and no wider than kPayloadBits.
    static constexpr bool fits(qsizetype payload) { return payload >= 0 && payload <= kMaxPayload; }
    /// Whether a payload of these two parts can be packed.
    static constexpr bool fits(qsizetype high, qsizetype low)
    {
        return high >= 0 && high <= kMaxHigh && low >= 0 && low <= kMaxLow;
    }

    constexpr Tag tag() const { return Tag(m_id & kMaxTag); }
    constexpr qsizetype payload() const { return qsizetype(m_id >> TagBits); }
    constexpr qsizetype high() const { return payload() >> LowBits; }
    constexpr qsizetype low() const { return payload() & kMaxLow; }
    /// The word to give createIndex.
    constexpr quintptr internalId() const { return m_id; }

    friend constexpr bool operator==(TreeIndexId, TreeIndexId) = default;

private:
    quintptr m_id = 0;
};

} // namespace rosarch
