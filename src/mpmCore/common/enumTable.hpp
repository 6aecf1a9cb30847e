// One table per enum: its values with the names dictionaries, logs and
// command lines use. name() gives a value's first name, parse() accepts
// every name listed (later entries of a value are accepted aliases), and
// validNames() lists the first names, space-separated, for error messages.
// The enums' name/parse/valid-names functions are one-line reads of their
// table, so no enum has hand-written parsing.
#pragma once
#include <array>
#include <cstddef>
#include <string>

namespace mpm {

template<class E>
struct EnumName
{
    E value;
    const char* name;
};

template<class E, std::size_t N>
struct EnumTable
{
    std::array<EnumName<E>, N> entries;

    const char* name(E e) const
    {
        for (const auto& x : entries) if (x.value == e) return x.name;
        return "?";
    }

    bool parse(const std::string& s, E& e) const
    {
        for (const auto& x : entries)
        {
            if (s == x.name) { e = x.value; return true; }
        }
        return false;
    }

    std::string validNames() const
    {
        std::string out;
        for (std::size_t i = 0; i < N; ++i)
        {
            bool alias = false;
            for (std::size_t j = 0; j < i; ++j) alias = alias || entries[j].value == entries[i].value;
            if (alias) continue;
            if (!out.empty()) out += ' ';
            out += entries[i].name;
        }
        return out;
    }
};

template<class E, std::size_t N>
constexpr EnumTable<E, N> enumTable(const EnumName<E> (&entries)[N])
{
    EnumTable<E, N> t{};
    for (std::size_t i = 0; i < N; ++i) t.entries[i] = entries[i];
    return t;
}

} // namespace mpm
