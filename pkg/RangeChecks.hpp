// Range checks for user-facing attributes: a bad value becomes a Python ValueError naming the
// class, the attribute, the value and the valid range.
#pragma once

#include <lib/base/Math.hpp>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace yade {
namespace toppling {

	struct Range {
		Real        lo, hi;
		bool        loOpen, hiOpen;
		const char* text;
		bool        contains(Real v) const
		{
			if (math::isnan(v)) return false;
			return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi);
		}
		static Range positive() { return { 0, std::numeric_limits<Real>::infinity(), true, false, "> 0" }; }
		static Range nonNegative() { return { 0, std::numeric_limits<Real>::infinity(), false, false, ">= 0" }; }
		static Range atLeastOne() { return { 1, std::numeric_limits<Real>::infinity(), false, false, ">= 1" }; }
		static Range dampingRatio() { return { 0, 1, false, true, "in [0, 1)" }; }
		static Range angle() { return { 0, Real(M_PI / 2), false, true, "in [0, pi/2) rad" }; }
	};

	inline void require(const char* owner, const char* attribute, Real value, const Range& range)
	{
		if (range.contains(value)) return;
		std::ostringstream msg;
		msg << owner << "." << attribute << " = " << value << " is invalid: it must be " << range.text << ".";
		throw std::invalid_argument(msg.str());
	}

} // namespace toppling
} // namespace yade
