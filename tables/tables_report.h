#pragma once
/// The report of `insmc tables` (montecarlo/report/report.h): the report's
/// Tables 3.1, 4.1, 4.2, 4.3, 5.1, 5.2 and the data of Figure 3.2, every
/// cell computed from the model beside the printed value: tables.md,
/// tables.csv (one long table) and Figure 3.2 drawn again (fig3_2).
#include "montecarlo/report/report.h"
#include "tables/generate.h"

namespace insmc::tables {

/// Markdown (one table per printed table) or csv (one long table).
mc::ReportOutline tables_report_outline();

mc::Report tables_report(const std::vector<TableCell>& cells, TableConvention convention);

}  // namespace insmc::tables
