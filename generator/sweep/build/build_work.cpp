#include "sweep/build/build_work.hpp"

#include <chrono>
#include <exception>

#include "common/error.hpp"

namespace towdb::sweep {

CaseEvent run_one(std::size_t work, const CaseSpec& spec, const io::ShipCatalog& catalog, const CaseRunner& runner) {
  CaseEvent e;
  e.work = work;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    e.outcome = runner(spec, catalog);
    e.outcome.validate();
    if (static_cast<int>(e.outcome.days.size()) != spec.days) {
      throw NumericalError("case runner returned " + std::to_string(e.outcome.days.size()) +
                           " daily maxima, expected days = " + std::to_string(spec.days));
    }
    e.ok = true;
  } catch (const InputError& x) {
    e.error = std::string("input error: ") + x.what();
  } catch (const NumericalError& x) {
    e.error = std::string("numerical error: ") + x.what();
  } catch (const std::exception& x) {
    e.error = std::string("error: ") + x.what();
  } catch (...) {
    e.error = "error: unknown exception";
  }
  if (!e.ok) e.outcome = CaseOutcome{};
  e.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return e;
}

}  // namespace towdb::sweep
