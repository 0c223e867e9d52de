// riseNotes of render_report.h: what issue 17's investigation found about each rise of the error
// with N or S. Hand-written from measurements made apart from the study (the commands are named);
// rerunning the study does not change this text, so check it against the table above it.
#include "bench/render/render_report.h"

namespace vem::bench {

std::string riseNotes() {
  return "(Investigation notes to come.)\n";
}

}  // namespace vem::bench
