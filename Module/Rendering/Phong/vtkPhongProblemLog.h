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

#include <cmath>   // for std::isfinite, std::abs, std::copysign
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
   * The largest magnitude of an uploaded colour, intensity, coefficient or exponent. A value
   * finite in double can be infinite in float (1e308), and an infinity times a zero in the
   * shader is NaN; a product of four values up to 1e9 stays finite in float (3.4e38).
   */
  static constexpr double LargestValue = 1.0e9;

  /**
   * The largest magnitude of an uploaded view-space light position: its squared length stays
   * finite in float.
   */
  static constexpr double LargestCoordinate = 1.0e18;

  /**
   * The largest attenuation coefficient: finite in float. Small scenes need large ones (q
   * scales as 1 / length^2), and the coefficients only enter the denominator, where a product
   * too large for float gives 1 / inf = 0, the right limit.
   */
  static constexpr double LargestAttenuation = 1.0e30;

  /**
   * The value when its magnitude is at most largest; otherwise +-largest, and the problem is
   * logged: describe(stream) names the value ("Light 0 (headlight) diffuse colour times
   * intensity").
   */
  template <typename Describe>
  double Bounded(double value, double largest, const Describe& describe, bool report = true)
  {
    if (!(std::abs(value) > largest))
    {
      return value;
    }
    if (report)
    {
      this->ReportBeyond(value, largest, describe);
    }
    return std::copysign(largest, value);
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
  template <typename Describe>
  void ReportBeyond(double value, double largest, const Describe& describe)
  {
    this->Report(
      [&](std::ostream& os)
      {
        describe(os);
        os << " " << value << " is beyond " << largest
           << " in magnitude, more than float arithmetic carries through the lighting; it is "
              "clamped to "
           << largest << ".";
      });
  }

  std::set<std::string> Problems;
};

#endif
// VTK-HeaderTest-Exclude: vtkPhongProblemLog.h
