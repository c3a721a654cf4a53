#pragma once
// The one guard of the scan module's C entry points (io/scan/scan_module.hpp):
// no exception leaves the module (one crossing dlopen'ed code is not
// something to rely on); each is turned into an outcome and a message naming
// the scan, which the core turns back into the exception.
#include <pcl/exceptions.h>

#include <exception>
#include <new>
#include <string>

#include "base/error.hpp"
#include "io/scan/scan_module.hpp"

namespace furrow::scan {

// Runs `work`; `task` names it in messages ("the scan reader", "the scan
// pre-processing"), `pcl_outcome` and `pcl_says` say whose fault a PCL
// exception is and how to put it: the reader's are the file's (PCL's
// parsers throw for files they reject outright), the pre-processing's are
// failures.
template <class Work>
int guarded_entry(const std::string& file, const char* task, ScanModuleOutcome pcl_outcome, const char* pcl_says,
                  std::string* message, Work&& work) {
  try {
    work();
    return static_cast<int>(ScanModuleOutcome::ok);
  } catch (const InputError& e) {
    *message = e.what();
    return static_cast<int>(ScanModuleOutcome::input_error);
  } catch (const std::bad_alloc&) {
    return static_cast<int>(ScanModuleOutcome::out_of_memory);
  } catch (const pcl::PCLException& e) {
    *message = file + ": " + pcl_says + ": " + e.detailedMessage();
    return static_cast<int>(pcl_outcome);
  } catch (const std::exception& e) {
    *message = file + ": " + task + " failed: " + e.what();
    return static_cast<int>(ScanModuleOutcome::failure);
  } catch (...) {
    *message = file + ": " + task + " failed with an unknown exception";
    return static_cast<int>(ScanModuleOutcome::failure);
  }
}

}  // namespace furrow::scan
