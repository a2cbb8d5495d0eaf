// The time types and encoding helpers of hlacore's IEEE 1516-2010 C++ API on their own: prints "name hex" for
// the encoding of a fixed set of values (tests/rti/test_rti1516e_cpp_encoding.py compares each with
// hlacore.omt's), then "ok <case>" for each check that holds; exits 1 if one does not.
#include <RTI/encoding/BasicDataElements.h>
#include <RTI/encoding/HLAfixedArray.h>
#include <RTI/encoding/HLAfixedRecord.h>
#include <RTI/encoding/HLAopaqueData.h>
#include <RTI/encoding/HLAvariableArray.h>
#include <RTI/encoding/HLAvariantRecord.h>
#include <RTI/LogicalTimeFactory.h>
#include <RTI/VariableLengthData.h>
#include <RTI/time/HLAfloat64TimeFactory.h>
#include <RTI/time/HLAinteger64TimeFactory.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace rti1516e;

namespace {

int failures = 0;
std::string failed;  // the first failed check of the running case

#define CHECK(condition) \
    ((condition) ? (void)0 : (void)(failed.empty() ? failed = std::string(#condition) + " (line " + std::to_string(__LINE__) + ")" : failed))

// Whether calling f throws E.
template <class E>
bool throws(std::function<void()> const& f) {
    try {
        f();
    } catch (E const&) {
        return true;
    } catch (...) {
        return false;
    }
    return false;
}

std::string hex(void const* data, size_t size) {
    std::string text;
    char digits[3];
    for (size_t i = 0; i < size; ++i) {
        std::snprintf(digits, sizeof digits, "%02x", static_cast<unsigned char const*>(data)[i]);
        text += digits;
    }
    return text;
}

std::string hex(VariableLengthData const& data) { return hex(data.data(), data.size()); }

// Every value shown must decode back (into a copy) to the same bytes, its length told right.
bool roundTrips = true;

void show(char const* name, DataElement const& element) {
    VariableLengthData data = element.encode();
    std::printf("%s %s\n", name, hex(data).c_str());
    auto copy = element.clone();
    copy->decode(data);
    if (hex(copy->encode()) != hex(data) || element.getEncodedLength() != data.size()) {
        std::printf("# %s does not round-trip\n", name);
        roundTrips = false;
    }
}

void showTime(char const* name, LogicalTime const& time) { std::printf("%s %s\n", name, hex(time.encode()).c_str()); }
void showInterval(char const* name, LogicalTimeInterval const& interval) {
    std::printf("%s %s\n", name, hex(interval.encode()).c_str());
}

void run(char const* name, std::function<void()> const& test) {
    failed.clear();
    try {
        test();
    } catch (Exception const& e) {
        std::wstring what = e.what();
        failed = "threw " + std::string(what.begin(), what.end());
    } catch (std::exception const& e) {
        failed = std::string("threw ") + e.what();
    }
    if (failed.empty()) {
        std::printf("ok %s\n", name);
    } else {
        std::printf("FAIL %s: %s\n", name, failed.c_str());
        ++failures;
    }
}

void showValues() {
    show("HLAASCIIchar", HLAASCIIchar('A'));
    show("HLAASCIIstring", HLAASCIIstring("hello"));
    show("HLAboolean_true", HLAboolean(true));
    show("HLAboolean_false", HLAboolean(false));
    show("HLAbyte", HLAbyte(Octet(0xab)));
    show("HLAoctet", HLAoctet(Octet(0x7f)));
    show("HLAfloat32BE", HLAfloat32BE(1.5f));
    show("HLAfloat32LE", HLAfloat32LE(-2.25f));
    show("HLAfloat64BE", HLAfloat64BE(3.141592653589793));
    show("HLAfloat64LE", HLAfloat64LE(-0.1));
    show("HLAinteger16BE", HLAinteger16BE(Integer16(-2)));
    show("HLAinteger16LE", HLAinteger16LE(Integer16(0x1234)));
    show("HLAinteger32BE", HLAinteger32BE(-123456));
    show("HLAinteger32LE", HLAinteger32LE(0x01020304));
    show("HLAinteger64BE", HLAinteger64BE(-1234567890123LL));
    show("HLAinteger64LE", HLAinteger64LE(0x0102030405060708LL));
    show("HLAoctetPairBE", HLAoctetPairBE(OctetPair(0x12, 0x34)));
    show("HLAoctetPairLE", HLAoctetPairLE(OctetPair(0x12, 0x34)));
    show("HLAunicodeChar", HLAunicodeChar(L'\u00e9'));
    show("HLAunicodeString", HLAunicodeString(L"h\u00e9\U0001D11E"));
    Octet bytes[] = {1, 2, 3};
    show("HLAopaqueData", HLAopaqueData(bytes, 3));

    HLAfixedArray shorts(HLAinteger16BE(), 3);
    for (Integer16 i = 0; i < 3; ++i) shorts.set(i, HLAinteger16BE(Integer16(i + 1)));
    show("fixed_int16x3", shorts);
    HLAfixedArray strings(HLAASCIIstring(), 2);
    strings.set(0, HLAASCIIstring("ab"));
    strings.set(1, HLAASCIIstring("c"));
    show("fixed_stringx2", strings);

    HLAvariableArray doubles{HLAfloat64BE()};
    doubles.addElement(HLAfloat64BE(1.0));
    doubles.addElement(HLAfloat64BE(2.0));
    show("variable_float64", doubles);
    show("variable_float64_empty", HLAvariableArray(HLAfloat64BE()));
    HLAvariableArray octets{HLAoctet()};
    for (char c : std::string("xyz")) octets.addElement(HLAoctet(c));
    show("variable_octet", octets);

    HLAfixedRecord record;
    record.appendElement(HLAoctet(1));
    record.appendElement(HLAinteger32BE(7));
    record.appendElement(HLAoctet(2));
    record.appendElement(HLAfloat64BE(0.5));
    show("record_padded", record);
    HLAfixedRecord nested;
    nested.appendElement(HLAinteger16BE(Integer16(-1)));
    HLAvariableArray longs{HLAinteger64BE()};
    longs.addElement(HLAinteger64BE(5));
    nested.appendElement(longs);
    nested.appendElement(record);
    show("record_nested", nested);

    HLAvariantRecord variant{HLAinteger32BE()};
    variant.addVariant(HLAinteger32BE(1), HLAfloat64BE());
    variant.addVariant(HLAinteger32BE(2), HLAASCIIstring());
    variant.setVariant(HLAinteger32BE(1), HLAfloat64BE(2.5));
    show("variant_float", variant);
    variant.setVariant(HLAinteger32BE(2), HLAASCIIstring("hi"));
    show("variant_string", variant);
    HLAvariantRecord small{HLAoctet()};
    small.addVariant(HLAoctet(3), HLAinteger32BE());
    small.setVariant(HLAoctet(3), HLAinteger32BE(-1));
    show("variant_octet_int32", small);

    showTime("HLAfloat64Time", HLAfloat64Time(1.5));
    showInterval("HLAfloat64Interval", HLAfloat64Interval(0.25));
    showTime("HLAinteger64Time", HLAinteger64Time(42));
    showInterval("HLAinteger64Interval", HLAinteger64Interval(-3));
}

void timeFloatArithmetic() {
    HLAfloat64Time t(1.5);
    t += HLAfloat64Interval(0.25);
    CHECK(t.getTime() == 1.75);
    t -= HLAfloat64Interval(1.0);
    CHECK(double(t) == 0.75);
    HLAfloat64Time later(2.0);
    CHECK(t < later && later > t && t <= later && later >= t && !(t == later) && t == HLAfloat64Time(0.75));
    HLAfloat64Interval d;
    d.setToDifference(later, t);
    CHECK(d.getInterval() == 1.25);
    d += HLAfloat64Interval(0.75);
    d -= HLAfloat64Interval(1.0);
    CHECK(double(d) == 1.0 && d > HLAfloat64Interval(0.5) && d <= HLAfloat64Interval(1.0));
    d.setEpsilon();
    CHECK(d.isEpsilon() && d.getInterval() == std::numeric_limits<double>::denorm_min() && d.getInterval() > 0);
    d.setZero();
    CHECK(d.isZero());
    t.setFinal();
    CHECK(t.isFinal() && std::isinf(t.getTime()) && t > later);
    t.setInitial();
    CHECK(t.isInitial() && t.getTime() == 0);
    LogicalTime& base = t;
    base = HLAfloat64Time(4.0);
    CHECK(t.getTime() == 4.0 && t.implementationName() == L"HLAfloat64Time");
}

void timeIntegerArithmetic() {
    HLAinteger64Time t(10);
    t += HLAinteger64Interval(5);
    t -= HLAinteger64Interval(2);
    CHECK(t.getTime() == 13 && Integer64(t) == 13);
    HLAinteger64Interval d;
    d.setToDifference(HLAinteger64Time(3), t);
    CHECK(d.getInterval() == -10 && d < HLAinteger64Interval(0));
    d.setEpsilon();
    CHECK(d.isEpsilon() && d.getInterval() == 1);
    t.setFinal();
    CHECK(t.isFinal() && t.getTime() == std::numeric_limits<Integer64>::max());
    CHECK(t.implementationName() == L"HLAinteger64Time" && d.implementationName() == L"HLAinteger64Time");
}

void timeEncoding() {
    HLAfloat64Time f(-7.125), g;
    g.decode(f.encode());
    CHECK(g == f);
    unsigned char buffer[8];
    CHECK(f.encode(buffer, sizeof buffer) == 8 && f.encodedLength() == 8);
    HLAinteger64Time i(-99), j;
    i.encode(buffer, sizeof buffer);
    j.decode(buffer, sizeof buffer);
    CHECK(j.getTime() == -99);
    HLAinteger64Interval k(1234567890123LL), l;
    l.decode(k.encode());
    CHECK(l == k);
    CHECK(throws<CouldNotEncode>([&] { f.encode(buffer, 7); }));
    HLAfloat64TimeFactory factory;
    CHECK(factory.decodeLogicalTime(f.encode())->toString() == L"-7.125");
    CHECK(*factory.decodeLogicalTimeInterval(HLAfloat64Interval(0.5).encode()) == HLAfloat64Interval(0.5));
}

void timeWrongLength() {
    unsigned char bytes[9] = {};
    VariableLengthData seven(bytes, 7);
    HLAfloat64Time f;
    HLAinteger64Interval i;
    HLAinteger64TimeFactory factory;
    CHECK(throws<CouldNotDecode>([&] { f.decode(seven); }));
    CHECK(throws<CouldNotDecode>([&] { i.decode(bytes, 9); }));
    CHECK(throws<CouldNotDecode>([&] { factory.decodeLogicalTime(seven); }));
    CHECK(throws<CouldNotDecode>([&] { factory.decodeLogicalTimeInterval(bytes, 0); }));
}

void timeWrongType() {
    HLAfloat64Time f(1);
    HLAinteger64Time i(1);
    CHECK(throws<InvalidLogicalTime>([&] { (void)(f < i); }));
    CHECK(throws<InvalidLogicalTime>([&] { (void)(i == f); }));
    CHECK(throws<InvalidLogicalTime>([&] { static_cast<LogicalTime&>(f) = i; }));
    CHECK(throws<InvalidLogicalTimeInterval>([&] { f += HLAinteger64Interval(1); }));
    CHECK(throws<InvalidLogicalTimeInterval>([&] { HLAinteger64Interval(1) += HLAfloat64Interval(1); }));
    CHECK(throws<InvalidLogicalTime>([&] { HLAfloat64Interval().setToDifference(f, i); }));
}

void timeOverflow() {
    HLAinteger64Time t;
    t.setFinal();
    t += HLAinteger64Interval(1);  // final plus anything is final
    CHECK(t.isFinal());
    HLAinteger64Time low(std::numeric_limits<Integer64>::min());
    low -= HLAinteger64Interval(1);
    CHECK(low.getTime() == std::numeric_limits<Integer64>::min());
    CHECK(throws<IllegalTimeArithmetic>(
        [&] { HLAinteger64Interval().setToDifference(t, HLAinteger64Time(-1)); }));
    HLAfloat64Time f;
    f.setFinal();
    CHECK(throws<IllegalTimeArithmetic>([&] { f -= HLAfloat64Interval(std::numeric_limits<double>::infinity()); }));
    // A positive interval always moves a time forward, however small beside it.
    for (double at : {1e6, 1.0, 4.45015e-308}) {
        HLAfloat64Time moved(at);
        HLAfloat64Interval epsilon;
        epsilon.setEpsilon();
        moved += epsilon;
        CHECK(moved > HLAfloat64Time(at));
        HLAfloat64Time tiny(at);
        tiny += HLAfloat64Interval(1e-12);
        CHECK(tiny > HLAfloat64Time(at));
        tiny -= HLAfloat64Interval(1e-12);
        CHECK(tiny < HLAfloat64Time(at) || tiny == HLAfloat64Time(at));
    }
}

void timeFactories() {
    for (auto make : {&HLAlogicalTimeFactoryFactory::makeLogicalTimeFactory,
                      &LogicalTimeFactoryFactory::makeLogicalTimeFactory}) {
        CHECK(make(L"")->getName() == L"HLAfloat64Time");
        CHECK(make(L"HLAfloat64Time")->getName() == L"HLAfloat64Time");
        auto integer = make(L"HLAinteger64Time");
        CHECK(integer && integer->getName() == L"HLAinteger64Time");
        CHECK(!make(L"HLAfloat32Time"));
        CHECK(integer->makeInitial()->isInitial() && integer->makeFinal()->isFinal());
        CHECK(integer->makeZero()->isZero() && integer->makeEpsilon()->isEpsilon());
        CHECK(dynamic_cast<HLAinteger64Time*>(integer->makeInitial().get()) != nullptr);
    }
    HLAfloat64TimeFactory f;
    CHECK(f.makeLogicalTime(2.5)->getTime() == 2.5 && f.makeLogicalTimeInterval(0.5)->getInterval() == 0.5);
    CHECK(f.makeFinal()->isFinal() && f.makeEpsilon()->isEpsilon());
    HLAinteger64TimeFactory i;
    CHECK(i.makeLogicalTime(7)->getTime() == 7 && i.makeLogicalTimeInterval(3)->getInterval() == 3);
}

void timeText() {
    std::wostringstream out;
    out << HLAfloat64Time(1.5) << L" " << HLAinteger64Interval(-4);
    CHECK(out.str() == L"1.5 -4");
}

void basicExternalMemory() {
    Integer32 x = 3;
    HLAinteger32BE e(&x);
    CHECK(e.get() == 3);
    e.set(5);
    CHECK(x == 5);
    e = 6;
    CHECK(x == 6 && Integer32(e) == 6);
    e.decode(HLAinteger32BE(-9).encode());
    CHECK(x == -9);
    HLAinteger32BE copy(e);
    copy.set(1);
    CHECK(x == -9 && copy.get() == 1);
    CHECK(throws<EncoderException>([&] { e.setDataPointer(nullptr); }));
    std::wstring text = L"abc";
    HLAunicodeString s;
    s.setDataPointer(&text);
    s.decode(HLAunicodeString(L"xy").encode());
    CHECK(text == L"xy");
    CHECK(HLAboolean(true).getEncodedLength() == 4 && HLAboolean().get() == false);
    CHECK(HLAunicodeString(L"\U0001D11E").getEncodedLength() == 8);
    CHECK(throws<EncoderException>([&] { HLAunicodeChar(wchar_t(0x1D11E)).encode(); }));
}

void decodeErrors() {
    unsigned char bytes[] = {0, 0, 0, 5, 'a', 'b'};
    VariableLengthData shortString(bytes, sizeof bytes);
    CHECK(throws<EncoderException>([&] { HLAASCIIstring().decode(shortString); }));
    CHECK(throws<EncoderException>([&] { HLAinteger16BE().decode(HLAinteger32BE(1).encode()); }));  // left over
    CHECK(throws<EncoderException>([&] { HLAinteger64LE().decode(HLAinteger32BE(1).encode()); }));  // short
    unsigned char negative[] = {0xff, 0xff, 0xff, 0xff};
    CHECK(throws<EncoderException>([&] { HLAvariableArray(HLAoctet()).decode(VariableLengthData(negative, 4)); }));
    HLAvariantRecord v{HLAinteger32BE()};
    v.addVariant(HLAinteger32BE(1), HLAoctet());
    CHECK(throws<EncoderException>([&] { v.decode(HLAinteger32BE(2).encode()); }));
    v.setDiscriminant(HLAinteger32BE(2));
    CHECK(throws<EncoderException>([&] { v.encode(); }));
    CHECK(throws<EncoderException>([&] { v.getVariant(); }));
    HLAinteger16BE untouched(7);
    CHECK(throws<EncoderException>([&] { untouched.decode(VariableLengthData(bytes, 1)); }) && untouched.get() == 7);
}

// A variable array of the strings "ab" and "c".
VariableLengthData strings() {
    HLAfixedArray two(HLAASCIIstring(), 2);
    two.set(0, HLAASCIIstring("ab"));
    two.set(1, HLAASCIIstring("c"));
    HLAvariableArray v{HLAASCIIstring()};
    v.addElement(two.get(0));
    v.addElement(two.get(1));
    return v.encode();
}

void composites() {
    HLAfixedArray a(HLAinteger32BE(), 2);
    CHECK(a.size() == 2 && a.getEncodedLength() == 8 && a.getOctetBoundary() == 4);
    CHECK(throws<EncoderException>([&] { a.set(0, HLAinteger16BE()); }));
    CHECK(throws<EncoderException>([&] { a.set(2, HLAinteger32BE()); }));
    CHECK(throws<EncoderException>([&] { a.get(5); }));
    CHECK(a.hasPrototypeSameTypeAs(HLAinteger32BE()) && !a.hasPrototypeSameTypeAs(HLAinteger32LE()));
    CHECK(a.isSameTypeAs(HLAfixedArray(HLAinteger32BE(), 2)) && !a.isSameTypeAs(HLAfixedArray(HLAinteger32BE(), 3)));
    CHECK(!a.isSameTypeAs(HLAinteger32BE()));
    HLAinteger32BE mine(1);
    a.setElementPointer(1, &mine);
    mine = 0x01020304;
    CHECK(hex(a.encode()) == "0000000001020304");
    a.decode(HLAfixedArray(HLAinteger32BE(9), 2).encode());
    CHECK(mine.get() == 9 && static_cast<HLAinteger32BE const&>(a[0]).get() == 9);
    auto copy = a.clone();
    mine = 4;
    CHECK(hex(copy->encode()) == "0000000900000009");  // a copy owns its elements

    HLAvariableArray v{HLAASCIIstring()};
    v.decode(strings());
    CHECK(v.size() == 2 && static_cast<HLAASCIIstring const&>(v.get(1)).get() == "c");
    CHECK(throws<EncoderException>([&] { v.addElement(HLAunicodeString()); }));
    CHECK(v.getOctetBoundary() == 4 && HLAvariableArray(HLAfloat64LE()).getOctetBoundary() == 8);

    HLAfixedRecord r;
    r.appendElement(HLAoctet());
    r.appendElement(HLAfloat64BE());
    CHECK(r.getOctetBoundary() == 8 && r.getEncodedLength() == 16 && HLAfixedRecord().getOctetBoundary() == 1);
    CHECK(throws<EncoderException>([&] { r.set(0, HLAfloat64BE()); }));
    CHECK(r.hasElementSameTypeAs(1, HLAfloat64BE()) && !r.hasElementSameTypeAs(2, HLAfloat64BE()));
    HLAfixedRecord other(r);
    CHECK(r.isSameTypeAs(other));
    other.appendElement(HLAoctet());
    CHECK(!r.isSameTypeAs(other));

    HLAvariantRecord w{HLAinteger32BE()};
    w.addVariant(HLAinteger32BE(1), HLAfloat64BE());
    CHECK(throws<EncoderException>([&] { w.addVariant(HLAinteger32BE(1), HLAoctet()); }));
    CHECK(throws<EncoderException>([&] { w.addVariant(HLAoctet(1), HLAoctet()); }));
    CHECK(throws<EncoderException>([&] { w.setVariant(HLAinteger32BE(1), HLAoctet()); }));
    CHECK(w.isSameTypeAs(HLAinteger32BE(1), HLAfloat64BE()) && w.hasMatchingDiscriminantTypeAs(HLAinteger32BE()));
    CHECK(throws<EncoderException>([&] { w.isSameTypeAs(HLAinteger32BE(5), HLAfloat64BE()); }));
    HLAfloat64BE value(8.0);
    w.setVariantPointer(HLAinteger32BE(1), &value);
    value = 0.5;
    w.decode(w.encode());
    CHECK(static_cast<HLAfloat64BE const&>(w.getVariant()).get() == 0.5 && w.getOctetBoundary() == 8);
    CHECK(static_cast<HLAinteger32BE const&>(w.getDiscriminant()).get() == 1);
    CHECK(w.isSameTypeAs(*w.clone()));
}

void opaqueData() {
    Octet storage[8] = {'a', 'b', 'c'};
    Octet* pointer = storage;
    HLAopaqueData o(&pointer, sizeof storage, 3);
    CHECK(o.dataLength() == 3 && o.bufferLength() == 8 && hex(o.encode()) == "00000003616263");
    o.decode(HLAopaqueData(reinterpret_cast<Octet const*>("wxyz"), 4).encode());
    CHECK(o.get() == storage && std::string(storage, 4) == "wxyz");
    CHECK(throws<EncoderException>([&] { HLAopaqueData(&pointer, 2, 3); }));
    HLAopaqueData copy(o);
    CHECK(copy.get() != storage && std::string(copy, copy.dataLength()) == "wxyz" && copy.getOctetBoundary() == 4);
}

void hashes() {
    CHECK(HLAinteger32BE(5).hash() == HLAinteger32BE(5).hash());
    CHECK(HLAinteger32BE(5).hash() != HLAinteger32BE(6).hash());
    CHECK(HLAASCIIstring("a").isSameTypeAs(HLAASCIIstring()) && !HLAASCIIstring().isSameTypeAs(HLAunicodeString()));
}

}  // namespace

int main() {
    showValues();
    run("roundtrip", [] { CHECK(roundTrips); });
    run("time_float_arithmetic", timeFloatArithmetic);
    run("time_integer_arithmetic", timeIntegerArithmetic);
    run("time_encoding", timeEncoding);
    run("time_wrong_length", timeWrongLength);
    run("time_wrong_type", timeWrongType);
    run("time_overflow", timeOverflow);
    run("time_factories", timeFactories);
    run("time_text", timeText);
    run("basic_external_memory", basicExternalMemory);
    run("decode_errors", decodeErrors);
    run("composites", composites);
    run("opaque_data", opaqueData);
    run("hashes", hashes);
    return failures ? 1 : 0;
}
