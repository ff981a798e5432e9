#include "core/exchange/step_file.hpp"

namespace isoparm::exchange::step {

std::string quoted(const std::string& text) {
    std::string out = "'";
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '\'' || c == '\\') out += ch;
        out += c >= 0x20 && c < 0x7f ? ch : '?';
    }
    return out + "'";
}

std::string ref(int id) {
    return "#" + std::to_string(id);
}

std::string list(const std::vector<std::string>& items) {
    std::string out = "(";
    for (std::size_t k = 0; k < items.size(); ++k) out += (k ? "," : "") + items[k];
    return out + ")";
}

int DataSection::add(std::string record) {
    records_.push_back(std::move(record));
    return static_cast<int>(records_.size());
}

std::string DataSection::file_text(const std::string& description, const std::string& name,
                                   const std::string& schema) const {
    // ISO 10303-21 8.2: FILE_DESCRIPTION (description, implementation level "2;1" = this
    // edition's conformance class 1), FILE_NAME (name, time stamp, author, organization,
    // preprocessor, originating system, authorization), FILE_SCHEMA.
    std::string out = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((" + quoted(description) +
                      "),'2;1');\nFILE_NAME(" + quoted(name) +
                      ",'2026-01-01T00:00:00',(''),(''),'isoparm','isoparm','');\nFILE_SCHEMA((" +
                      quoted(schema) + "));\nENDSEC;\nDATA;\n";
    for (std::size_t k = 0; k < records_.size(); ++k)
        out += "#" + std::to_string(k + 1) + "=" + records_[k] + ";\n";
    return out + "ENDSEC;\nEND-ISO-10303-21;\n";
}

} // namespace isoparm::exchange::step
