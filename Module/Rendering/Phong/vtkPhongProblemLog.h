/**
 * @class   vtkPhongProblemLog
 * @brief   collects the bad scene parameters found while planning and uploading, once each
 *
 * The lighting code substitutes a documented value for every parameter it cannot use (a NaN
 * colour, a negative intensity, ...) and says so. The same bad value is met every frame and by
 * every primitive: the log keeps each message once until the mapper takes them all and
 * reports them through its error macro (vtkPhongMapperCore::ReportProblems).
 *
 * Messages are written by a callable that receives an std::ostream, so they are formatted only
 * when a value is bad.
 *
 * Private to the module.
 */

#ifndef vtkPhongProblemLog_h
#define vtkPhongProblemLog_h

#include <cmath>   // for std::isfinite
#include <set>     // for std::set
#include <sstream> // for std::ostringstream
#include <string>  // for std::string

class vtkPhongProblemLog
{
public:
  /**
   * Log the message that describe(stream) writes.
   */
  template <typename Describe>
  void Report(const Describe& describe)
  {
    std::ostringstream message;
    describe(message);
    this->Problems.insert(message.str());
  }

  /**
   * The value when it is finite and >= 0; otherwise 0, and the problem is logged.
   */
  template <typename Describe>
  double NonNegative(double value, const Describe& describe)
  {
    if (value >= 0.0 && std::isfinite(value))
    {
      return value;
    }
    this->Report(describe);
    return 0.0;
  }

  /**
   * The value when it is finite; otherwise 0, and the problem is logged when report is true.
   */
  template <typename Describe>
  double Finite(double value, bool report, const Describe& describe)
  {
    if (std::isfinite(value))
    {
      return value;
    }
    if (report)
    {
      this->Report(describe);
    }
    return 0.0;
  }

  /**
   * The logged messages, one per line, in sorted order; the log is empty afterwards.
   */
  std::string Take()
  {
    std::string text;
    for (const auto& problem : this->Problems)
    {
      text += problem + "\n";
    }
    this->Problems.clear();
    return text;
  }

  std::size_t GetNumberOfProblems() const { return this->Problems.size(); }

private:
  std::set<std::string> Problems;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongProblemLog.h
