// A Beast response body that sends one byte range of a file in 64 KiB reads, so downloads of
// large results (and Range requests) never load a file into memory.
#pragma once

#include <boost/beast/core/file.hpp>
#include <boost/beast/http/message.hpp>
#include <boost/optional.hpp>
#include <cstdint>
#include <utility>

namespace kontakt::server {

struct FileRangeBody {
  struct value_type {
    boost::beast::file file;   ///< opened and positioned at the range's first byte
    std::uint64_t length = 0;  ///< bytes to send
  };

  static std::uint64_t size(const value_type& body) { return body.length; }

  class writer {
   public:
    using const_buffers_type = boost::asio::const_buffer;

    template <bool isRequest, class Fields>
    writer(boost::beast::http::header<isRequest, Fields>&, value_type& body)
        : body_(body), remain_(body.length) {}

    void init(boost::beast::error_code& ec) { ec = {}; }

    boost::optional<std::pair<const_buffers_type, bool>> get(boost::beast::error_code& ec) {
      const std::size_t amount =
          remain_ > sizeof buffer_ ? sizeof buffer_ : static_cast<std::size_t>(remain_);
      if (amount == 0) {
        ec = {};
        return boost::none;
      }
      const std::size_t n = body_.file.read(buffer_, amount, ec);
      if (ec) return boost::none;
      if (n == 0) {  // the file shrank under us
        ec = boost::beast::http::error::short_read;
        return boost::none;
      }
      remain_ -= n;
      return {{const_buffers_type(buffer_, n), remain_ > 0}};
    }

   private:
    value_type& body_;
    std::uint64_t remain_;
    char buffer_[65536];
  };
};

}  // namespace kontakt::server
