// A plain row-major 2D array: colour, depth, triangle-id and normal buffers.
// Row 0 is the top of the image; pixel (x, y) is at index y * width + x.
#pragma once

#include <cstddef>
#include <vector>

namespace rl {

// Columns [begin, end) of a band of rows; empty when begin >= end.
struct ColumnRange {
    int begin = 0;
    int end = 0;
    bool operator==(const ColumnRange&) const = default;
};

template <typename T>
class Image {
public:
    Image() = default;
    Image(int width, int height, const T& fill = T())
        : m_width(width),
          m_height(height),
          m_pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill) {}

    // The same as assigning Image(width, height, fill), but keeping the memory already held,
    // so that a buffer reused from frame to frame costs no new pages.
    void reset(int width, int height, const T& fill = T()) {
        m_width = width;
        m_height = height;
        m_pixels.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
    }

    // The size changed without filling: pixels kept from an earlier frame keep their values
    // and new ones are T(); for a caller that writes every pixel itself.
    void resize(int width, int height) {
        m_width = width;
        m_height = height;
        m_pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
    }

    int width() const { return m_width; }
    int height() const { return m_height; }
    bool empty() const { return m_pixels.empty(); }
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < m_width && y < m_height; }

    T& at(int x, int y) { return m_pixels[index(x, y)]; }
    const T& at(int x, int y) const { return m_pixels[index(x, y)]; }
    T* row(int y) { return m_pixels.data() + index(0, y); }
    const T* row(int y) const { return m_pixels.data() + index(0, y); }

    const std::vector<T>& pixels() const { return m_pixels; }
    std::vector<T>& pixels() { return m_pixels; }

    bool operator==(const Image& other) const = default;

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(m_width) +
               static_cast<std::size_t>(x);
    }

    int m_width = 0;
    int m_height = 0;
    std::vector<T> m_pixels;
};

}  // namespace rl
