#pragma once
// The CSS of Plumb's HTML reports (registration and network): one look for every report.

namespace plumb::report {

inline constexpr const char* kReportStyle = R"(
body{font-family:sans-serif;max-width:1000px;margin:1em auto;color:#222;line-height:1.35}
h1{font-size:1.5em;margin-bottom:0}h2{font-size:1.15em;border-bottom:1px solid #bbb;margin-top:1.6em}
table{border-collapse:collapse;width:100%;font-size:0.9em}
td,th{border:1px solid #ddd;padding:3px 6px;text-align:left;vertical-align:top}
th{background:#f2f2f2}td.v{white-space:nowrap;font-family:monospace}
.verdict{padding:0.6em 1em;border-radius:4px;border:2px solid}
.usable{background:#e8f5e9;border-color:#2e7d32}.check-visually{background:#fff8e1;border-color:#f9a825}
.failed{background:#ffebee;border-color:#c62828}figure{margin:1em 0}figcaption{font-size:0.85em;color:#555}
.sign td{height:2.2em}@media print{h2{page-break-after:avoid}figure{page-break-inside:avoid}}
)";

}  // namespace plumb::report
