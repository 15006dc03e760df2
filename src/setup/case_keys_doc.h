// case_keys_doc.h: the key tables of docs/case-reference.md, generated from the key table.
//
// The document holds each table between marker lines,
//   <!-- keys:integrator begin -->  ...  <!-- keys:integrator end -->
// (ids "TABLE" or "TABLE:SECTION", as key_table_ids() lists them, and "restartable": the keys
// a restart may change); the prose around them is written by hand. 'swarf case keys --update
// FILE' rewrites the blocks, and a test fails when the document and the key table differ.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace swarf {

/// The ids of the generated tables, in document order: "workpiece", ..., "integrator:newmark", ...
std::vector<std::string> key_table_ids();
/// One markdown table: key | type | unit | default | allowed | meaning. Throws std::invalid_argument for an unknown id.
std::string key_table_markdown(std::string_view id);
/// Every table, each between its marker lines (the restartable keys last).
std::string key_tables_markdown();
/// One line per key, "TABLE.KEY  TYPE  UNIT  DEFAULT", aligned ('swarf case keys').
std::string key_list_text();
/// 'document' with every marker block's content replaced by its generated table. Throws
/// std::runtime_error naming the id when a block is unknown or unclosed, or a table has no block.
std::string update_key_tables(const std::string& document);
/// Empty when the document's blocks hold the generated tables; otherwise names the first
/// differing table and key and shows both lines.
std::string key_tables_difference(const std::string& document);
/// update_key_tables on a file, rewritten in place; throws InputError naming the file.
void update_key_tables_file(const std::string& path);

}  // namespace swarf
