"""Number rules of the awk programs and bash printf calls that first wrote
docs/paper-reproduction.md, kept so that the same raw outputs give the same page.

awk (mawk) reads numbers with strtod into doubles, divides by zero into inf or NaN,
prints computed numbers with OFMT %.6g (integral ones as integers) and fields as their
text; bash's printf reads its arguments with strtold, so %f there rounds the 80-bit long
double of the text.
"""
import math
import re
from fractions import Fraction

_BLANKS = " \t\n"
_DECIMAL = r"(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
_NUMBER_PREFIX = re.compile(r"[ \t\n]*([+-]?(?:" + _DECIMAL + r"|(?i:inf(?:inity)?|nan)))")
_WHOLE_DECIMAL = re.compile(r"[ \t\n]*[+-]?" + _DECIMAL + r"[ \t\n]*")
_FIELD_SEPARATORS = re.compile(r"[ \t\n]+")
_LONG_DOUBLE_DIGITS = 64
_AWK_MAX_INT = 2**31 - 1  # mawk's integers (%d, integral prints) are C ints


def fields(line):
    """awk's default field splitting: runs of blanks, none at either end."""
    stripped = line.strip(_BLANKS)
    return _FIELD_SEPARATORS.split(stripped) if stripped else []


def lines(text):
    """awk's records: newline-separated, without the empty one after a final newline."""
    records = text.split("\n")
    if records and records[-1] == "":
        records.pop()
    return records


def looks_numeric(text):
    """Whether awk treats a field or a -v value as a number in comparisons."""
    return text is not None and _WHOLE_DECIMAL.fullmatch(text) is not None


def _leading(text):
    match = _NUMBER_PREFIX.match(text or "")
    return match.group(1) if match else None


def number(text):
    """awk's value of a string: its leading number, 0 without one (None is unset)."""
    literal = _leading(text)
    return float(literal) if literal else 0.0


def positive(text):
    """awk's `b > 0` for a -v value: numeric when it looks numeric, else text order."""
    if text is None:
        return False
    if looks_numeric(text):
        return number(text) > 0
    return text > "0"


def truthy(text):
    """awk's truth of a field copied into a variable: a number unless it is text."""
    if text is None or text == "":
        return False
    if looks_numeric(text):
        return number(text) != 0
    return True


def divide(a, b):
    """IEEE division as awk does it: x/0 is a signed infinity, 0/0 the x86 default NaN."""
    if b != 0 or math.isnan(b):
        return a / b
    if a == 0:
        return -math.nan
    if math.isnan(a):
        return a
    negative = (math.copysign(1, a) < 0) != (math.copysign(1, b) < 0)
    return -math.inf if negative else math.inf


def fmt(spec, value):
    """C's printf of one double (`spec` like ".2f"), with NaN's sign as glibc writes it."""
    if math.isnan(value):
        return "-nan" if math.copysign(1, value) < 0 else "nan"
    return ("%" + spec) % value


def integer(value):
    """mawk's %d of a double: truncated toward zero, clamped to a C int (NaN at the bottom)."""
    if value >= _AWK_MAX_INT:
        return _AWK_MAX_INT
    if value > -_AWK_MAX_INT:
        return math.trunc(value)
    return -_AWK_MAX_INT


def print_number(value):
    """How awk's print writes a computed number: integral as an integer, else %.6g."""
    if -_AWK_MAX_INT <= value <= _AWK_MAX_INT and value == math.trunc(value):
        return "%d" % math.trunc(value)
    return fmt(".6g", value)


def median(values):
    """`sort -g | awk` median of one value per line; 0 for none.

    An odd count keeps the middle text as it was; an even one prints the mean of the
    two middle values as awk prints numbers."""
    ordered = sorted(values, key=general_numeric_key)
    firsts = [(fields(v) or [""])[0] for v in ordered]
    count = len(firsts)
    if count % 2:
        return firsts[(count + 1) // 2 - 1]
    if count == 0:
        return print_number(0.0)
    middle = (number(firsts[count // 2 - 1]) + number(firsts[count // 2])) / 2
    return print_number(middle)


def general_numeric_key(line):
    """GNU sort -g: lines without a leading number first, then NaN, then by value;
    equal values bytewise."""
    literal, tie = _leading(line), line.encode("utf-8", "surrogateescape")
    if literal is None:
        return (0, 0, tie)
    value = float(literal)
    if math.isnan(value):
        return (1, 0, tie)
    if math.isinf(value):
        return (2, value, tie)
    return (2, _long_double(Fraction(literal)), tie)


def _long_double(exact):
    """The x87 80-bit long double nearest to an exact value (64-bit significand)."""
    if exact == 0:
        return exact
    magnitude = abs(exact)
    shift = magnitude.numerator.bit_length() - magnitude.denominator.bit_length() - (_LONG_DOUBLE_DIGITS - 1)
    scaled = magnitude / Fraction(2) ** shift
    while scaled >= 2**_LONG_DOUBLE_DIGITS:
        shift += 1
        scaled /= 2
    while scaled < 2 ** (_LONG_DOUBLE_DIGITS - 1):
        shift -= 1
        scaled *= 2
    rounded = round(scaled) * Fraction(2) ** shift
    return rounded if exact > 0 else -rounded


def bash_fixed(decimals, text):
    """bash's `printf %.Nf TEXT`: the long double of TEXT's leading number, rounded
    half to even on its exact binary value."""
    literal = _leading(text) or "0"
    negative = literal.startswith("-")
    special = float(literal)
    if math.isnan(special) or math.isinf(special):
        return ("-" if negative else "") + ("nan" if math.isnan(special) else "inf")
    value = _long_double(Fraction(literal))
    scaled = round(abs(value) * 10**decimals)
    digits = str(scaled).rjust(decimals + 1, "0")
    body = digits[:-decimals] + "." + digits[-decimals:] if decimals else digits
    return ("-" if negative else "") + body
