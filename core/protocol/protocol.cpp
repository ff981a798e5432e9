// `isoparm geom`: request dispatch through the op table, batches, exit statuses.
#include "core/protocol/protocol.hpp"

#include <array>
#include <iostream>
#include <iterator>
#include <new>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/geom/work_budget.hpp"
#include "core/json/input_file.hpp"
#include "core/json/out_of_memory.hpp"
#include "core/json/reader.hpp"
#include "core/json/writer.hpp"
#include "core/protocol/detail.hpp"
#include "core/protocol/op_construct.hpp"
#include "core/protocol/stream.hpp"

namespace isoparm::protocol {

using geom::Error;
using geom::ErrorCode;
using protocol::json;

namespace {

struct OpEntry {
    std::string_view name;
    protocol::OpHandler handler;
};

// Adding an op is one line here and one file (see detail.hpp).
constexpr std::array<OpEntry, 30> op_table = {{
    {"evaluate", protocol::op_evaluate},
    {"basis", protocol::op_basis},
    {"deboor", protocol::op_deboor},
    {"curvature", protocol::op_curvature},
    {"blossom", protocol::op_blossom},
    {"insert_knot", protocol::op_insert_knot},
    {"elevate_degree", protocol::op_elevate_degree},
    {"split", protocol::op_split},
    {"interpolate", protocol::op_interpolate},
    {"approximate", protocol::op_approximate},
    {"remove_knot", protocol::op_remove_knot},
    {"reduce_degree", protocol::op_reduce_degree},
    {"tessellate", protocol::op_tessellate},
    {"polygonize", protocol::op_polygonize},
    {"make_compatible", protocol::op_make_compatible},
    {"ruled", protocol::op_ruled},
    {"revolve", protocol::op_revolve},
    {"swing", protocol::op_swing},
    {"sweep", protocol::op_sweep},
    {"skin", protocol::op_skin},
    {"coons", protocol::op_coons},
    {"gordon", protocol::op_gordon},
    {"convert", protocol::op_convert},
    {"close", protocol::op_close},
    {"split_knot", protocol::op_split_knot},
    {"de_casteljau", protocol::op_de_casteljau},
    {"export", protocol::op_export},
    {"import", protocol::op_import},
    {"classify", protocol::op_classify},
    {"area", protocol::op_area},
}};

json error_response(const Error& e) {
    json err = json::object();
    err["code"] = geom::name_of(e.code);
    err["message"] = e.message;
    if (e.has_path) err["path"] = e.path;
    return json{{"ok", false}, {"error", std::move(err)}};
}

json out_of_memory_response() {
    return error_response(geom::make_error_nopath(ErrorCode::limit, out_of_memory_message));
}

std::string known_ops() {
    std::string list;
    for (const OpEntry& op : op_table) {
        if (!list.empty()) list += ", ";
        list += op.name;
    }
    return list;
}

protocol::OpResult dispatch(const json& request) {
    if (!request.is_object())
        return protocol::schema_error("a request is a JSON object with an \"op\" field", "");
    const json* op = protocol::find_member(request, "op");
    if (!op) return protocol::missing_member("", "op");
    if (!op->is_string()) return protocol::schema_error("op must be a string", "/op");
    const std::string& name = op->get_ref<const std::string&>();
    for (const OpEntry& entry : op_table)
        if (entry.name == name) return entry.handler(request);
    return geom::make_error(
        ErrorCode::unknown_op,
        "unknown op '" + short_name(name) + "' (available: " + known_ops() + ")", "/op");
}

// One request with the reader's problems inside it (paths relative to the request).
json respond(const json& request, const std::vector<Error>& problems) {
    if (!problems.empty()) return error_response(problems.front());
    arm_memory_reserve(); // spent by an earlier request of the batch: set one aside again
    try {
        protocol::OpResult r = dispatch(request);
        if (!r) return error_response(r.error());
        json out = std::move(r).value();
        out["ok"] = true;
        return out;
    } catch (const std::bad_alloc&) {
        // The reserve (out_of_memory.hpp) let the unwinding finish; set a new one aside.
        arm_memory_reserve();
        return out_of_memory_response();
    } catch (const std::exception& e) {
        // Exceptions stop here: a bug must still produce a well-formed answer.
        return error_response(geom::make_error_nopath(ErrorCode::internal,
                                                      std::string("internal error: ") + e.what()));
    }
}

bool succeeded(const json& response) {
    const auto it = response.find("ok");
    return it != response.end() && it->is_boolean() && it->get<bool>();
}

// The reader's problems of a batch, grouped by element with paths relative to it, in one
// pass (a hostile batch may hold a problem in each of a million elements).
std::unordered_map<std::size_t, std::vector<Error>>
problems_by_element(const std::vector<Error>& problems) {
    std::unordered_map<std::size_t, std::vector<Error>> out;
    for (const Error& p : problems) {
        // "/12/x" -> element 12, path "/x".
        std::size_t k = 1, index = 0;
        while (k < p.path.size() && p.path[k] >= '0' && p.path[k] <= '9')
            index = index * 10 + static_cast<std::size_t>(p.path[k++] - '0');
        if (k == 1 || p.path.empty() || p.path[0] != '/') continue; // not inside an element
        Error e = p;
        e.path = p.path.substr(k);
        out[index].push_back(std::move(e));
    }
    return out;
}

} // namespace

json handle_request(const json& request) {
    return respond(request, {});
}

json input_error_response(const Error& e) {
    return error_response(e);
}

int run_protocol(std::istream& in, std::ostream& out, std::ostream& err) {
    std::string text;
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
        const auto n = static_cast<std::size_t>(in.gcount());
        if (text.size() + n > max_input_bytes) {
            std::string s;
            write_json(s, error_response(geom::make_error_nopath(
                              ErrorCode::limit, "the input is larger than 256 MiB; requests may "
                                                "be at most 256 MiB")));
            out << s << "\n";
            return 1;
        }
        text.append(buf, n);
    }
    if (in.bad()) {
        err << "isoparm geom: cannot read the input\n";
        return 2;
    }
    return run_protocol_text(std::move(text), out, err);
}

namespace {

// Appends one response's text; running out of memory while writing it replaces it with a
// `limit` response (the text written so far for it is dropped). Returns whether it succeeded.
bool append_response(std::string& s, json response) {
    const ReleaseJsonOnExit release(response); // a big answer is freed without allocating
    const std::size_t mark = s.size();
    try {
        write_json(s, response);
        return succeeded(response);
    } catch (const std::bad_alloc&) {
        s.resize(mark);
        s.shrink_to_fit();
        arm_memory_reserve();
        write_json(s, out_of_memory_response());
        return false;
    }
}

// A streamed answer (tessellate, polygonize, evaluate: stream.hpp). Errors and
// running out of memory happen before its first byte is written and are ordinary error
// responses; once writing starts nothing allocates.
bool stream_response(std::string& s, std::ostream& out, const json& request, StreamedOp op) {
    arm_memory_reserve();
    const std::size_t mark = s.size();
    try {
        geom::Expected<StreamedAnswer> answer = op(request);
        if (!answer) {
            write_json(s, error_response(answer.error()));
            return false;
        }
        s.reserve(s.size() + stream_chunk_bytes + 4096); // then writing allocates nothing
        (*answer)(s, out);
        return true;
    } catch (const std::bad_alloc&) {
        s.resize(mark);
        arm_memory_reserve();
        write_json(s, out_of_memory_response());
        return false;
    } catch (const std::exception& e) {
        s.resize(mark);
        write_json(s, error_response(geom::make_error_nopath(
                          ErrorCode::internal, std::string("internal error: ") + e.what())));
        return false;
    }
}

// One request's answer into `s` (streamed answers may already be partly written to `out`).
bool answer_into(std::string& s, std::ostream& out, const json& request,
                 const std::vector<Error>& problems) {
    if (problems.empty())
        if (const StreamedOp op = streamed_op_of(request))
            return stream_response(s, out, request, op);
    return append_response(s, respond(request, problems));
}

int answer(std::string text, std::ostream& out, std::ostream& err) {
    geom::Expected<ReadJson> read = read_json(text);
    text.clear();
    text.shrink_to_fit();
    if (!read) {
        if (read.error().code == ErrorCode::parse) {
            err << "isoparm geom: the input is not JSON: " << read.error().message << "\n";
            return 2;
        }
        std::string s;
        write_json(s, error_response(read.error()));
        out << s << "\n";
        return 1;
    }
    json& value = read->value;
    const ReleaseJsonOnExit release(value); // however this ends, the request is freed safely
    const std::vector<Error>& problems = read->problems;
    std::string s;
    int status = 0;
    if (value.is_array()) {
        // A batch: each element answered on its own, paths relative to the element, and
        // written as soon as it is answered (memory follows one answer, not the batch).
        const auto by_element = problems_by_element(problems);
        static const std::vector<Error> none;
        const geom::BatchBudget budget; // one work budget for the whole batch
        out << '[';
        for (std::size_t i = 0; i < value.size(); ++i) {
            const auto found = by_element.find(i);
            if (i > 0) s += ", ";
            if (!answer_into(s, out, value[i], found == by_element.end() ? none : found->second))
                status = 1;
            release_json(value[i]); // answered: its memory is no longer needed
            out << s;
            s.clear();
            s.shrink_to_fit();
        }
        s += ']';
    } else {
        if (!answer_into(s, out, value, problems)) status = 1;
    }
    s += '\n';
    out << s;
    out.flush();
    return status;
}

} // namespace

int run_protocol_text(std::string text, std::ostream& out, std::ostream& err) {
    arm_memory_reserve();
    try {
        return answer(std::move(text), out, err);
    } catch (const std::bad_alloc&) {
        // Reading the input itself ran out of memory (an answer never gets here).
        arm_memory_reserve();
        std::string s;
        write_json(s, out_of_memory_response());
        out << s << "\n";
        out.flush();
        return 1;
    }
}

} // namespace isoparm::protocol
