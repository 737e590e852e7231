// TlsCredentials: the certificate chain and private key the browser viewer's https page and wss
// socket present (--tls-cert, --tls-key, PEM files), read at start and again on SIGHUP. Each
// connection takes the context in force when it is accepted, so a renewed certificate reaches new
// connections while open ones keep theirs; a reload that fails keeps the old one and says why.
#pragma once

#include <asio/ssl/context.hpp>

#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace ocean::server {

class TlsCredentials {
 public:
  // Reads both files; nullopt with a reason naming the file and OpenSSL's complaint.
  static std::optional<TlsCredentials> load(const std::string& cert_file, const std::string& key_file, std::string& error);

  // The context for a connection accepted now (any thread).
  std::shared_ptr<asio::ssl::context> current() const;
  // Reads the files again: empty when the new pair is in force, else why the old one stays.
  std::string reload();
  const std::string& cert_file() const { return cert_file_; }

  TlsCredentials(TlsCredentials&& other) noexcept;

 private:
  TlsCredentials(std::string cert_file, std::string key_file) : cert_file_(std::move(cert_file)), key_file_(std::move(key_file)) {}
  std::shared_ptr<asio::ssl::context> read(std::string& error) const;

  std::string cert_file_, key_file_;
  mutable std::mutex mutex_;
  std::shared_ptr<asio::ssl::context> context_;
};

}  // namespace ocean::server
