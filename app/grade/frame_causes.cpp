#include "app/grade/frame_causes.h"

#include "app/util/format.h"

namespace shadelab {

namespace {

std::string bracketed(const ViewRange& r) {
  return "[" + formatSignificant(r.low) + ", " + formatSignificant(r.high) + "]";
}

}  // namespace

std::string nonFiniteCause(const ConfigurationResult& c) {
  std::string s = "Your frame holds non-finite values in " + quoted(c.name) + ": " + c.nonFiniteText + ". ";
  if (c.nanPixels)
    return s +
           "A NaN comes from 0/0 (an average over no samples), normalize() of a zero vector, or sqrt() or log() "
           "of a negative number: guard the case that makes the divisor or the length 0.";
  return s + "An Inf comes from dividing a non-zero value by 0 or from log(0): guard the divisor.";
}

Cause propertyCause(const ConfigurationResult& c, const ViewRange& range) {
  const std::string in = " in " + quoted(c.name);
  if (c.outOfRangePct > 0.5)
    return {"property:out-of-range",
            "Your values leave the view's range, " + bracketed(range) + "," + in + " (" +
                formatFixed(c.outOfRangePct, 1) + " % of the pixels; their median is " +
                formatSignificant(c.outsideMedian, 3) +
                "), where the solution's stay inside it. Values go there from a result outside the range returned "
                "for one of the cases (lit or in shadow, say), a sum where an average was meant, or weights that "
                "do not add up to 1."};
  // An umbra that does not reach shadow has more than one usual cause (the comparison, taps or a
  // search that leave the occluder, too few blockers found): what was seen, and the candidates.
  if (c.umbraLevel > 0.1)
    return {"seen:umbra", "Where the truth and the solution are in full shadow, yours is not" + in + " (it averages " +
                              formatFixed(c.umbraLevel, 2) +
                              " of the way to lit): points the occluder hides count as lit there. Look at what "
                              "decides that a tap is occluded, and at where the taps land."};
  // A lit region that is not lit and edges of another width have several usual causes each (a
  // bias, taps that land elsewhere, a filter that does not average its comparisons, an early
  // return): the frames cannot tell which, so what was seen is said, with where to look.
  if (c.litLevel > 0.1)
    return {"seen:lit", "Where the truth and the solution are fully lit, yours is not" + in + " (" +
                            formatFixed(c.litLevel, 2) +
                            " of the way to shadow): points nothing hides count as shadowed there. Look at what "
                            "decides that a point or a tap is occluded, and at where the taps land."};
  if (c.edgeWidthRatio > 1.5 || c.edgeWidthRatio < 0.67)
    return {"seen:edge-width", "Your soft edges" + in + " are " + formatFixed(c.edgeWidthRatio, 2) +
                                   " times as wide as the solution's. Look at what sets an edge's width: the "
                                   "footprint the taps cover, and how each tap's comparison adds to the result."};
  return {};
}

std::string propertyObservation(const ConfigurationResult& c, const ViewRange& range) {
  const std::string in = "In " + quoted(c.name) + ", ";
  if (c.outOfRangePct > 0.5)
    return in + formatFixed(c.outOfRangePct, 1) + " % of your values leave the view's range, " + bracketed(range) +
           " (their median is " + formatSignificant(c.outsideMedian, 3) + ").";
  if (c.umbraLevel > 0.1)
    return in + "where the truth and the solution are in full shadow, yours averages " + formatFixed(c.umbraLevel, 2) +
           " of the way to lit.";
  if (c.litLevel > 0.1)
    return in + "where the truth and the solution are fully lit, yours is " + formatFixed(c.litLevel, 2) +
           " of the way to shadow.";
  if (c.edgeWidthRatio > 1.5 || c.edgeWidthRatio < 0.67)
    return in + "your soft edges are " + formatFixed(c.edgeWidthRatio, 2) + " times as wide as the solution's.";
  return {};
}

}  // namespace shadelab
