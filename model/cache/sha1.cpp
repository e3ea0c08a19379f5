#include "cache/sha1.h"

#include <openssl/evp.h>

#include <stdexcept>

namespace rosarch {

namespace {

/// The algorithm, fetched once: an implicit fetch on every digest costs more than hashing a
/// small file.
const EVP_MD *sha1()
{
    static EVP_MD *const md = EVP_MD_fetch(nullptr, "SHA1", nullptr);
    if (!md)
        throw std::runtime_error("OpenSSL has no SHA-1");
    return md;
}

} // namespace

struct Sha1::Context
{
    EVP_MD_CTX *ctx = EVP_MD_CTX_new();
    ~Context() { EVP_MD_CTX_free(ctx); }
};

Sha1::Sha1() : m_context(std::make_unique<Context>())
{
    if (!m_context->ctx || EVP_DigestInit_ex(m_context->ctx, sha1(), nullptr) != 1)
        throw std::runtime_error("OpenSSL could not start a SHA-1 digest");
}

Sha1::~Sha1() = default;

void Sha1::addData(QByteArrayView bytes)
{
    if (!bytes.isEmpty())
        EVP_DigestUpdate(m_context->ctx, bytes.data(), size_t(bytes.size()));
}

QByteArray Sha1::result()
{
    QByteArray digest(20, Qt::Uninitialized);
    unsigned int size = 0;
    EVP_DigestFinal_ex(m_context->ctx, reinterpret_cast<unsigned char *>(digest.data()), &size);
    digest.truncate(qsizetype(size));
    return digest;
}

QByteArray Sha1::hash(QByteArrayView bytes)
{
    QByteArray digest(20, Qt::Uninitialized);
    unsigned int size = 0;
    if (EVP_Digest(bytes.data(), size_t(bytes.size()),
                   reinterpret_cast<unsigned char *>(digest.data()), &size, sha1(), nullptr) != 1)
        throw std::runtime_error("OpenSSL could not compute a SHA-1 digest");
    digest.truncate(qsizetype(size));
    return digest;
}

} // namespace rosarch
