// The stand-in AUTOMATIC program (see automatic_program.hpp).
#include "pac/sim/automatic_program.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "pac/sim/automatic_module.hpp"

namespace pac::sim {

namespace {

constexpr int kMaxElement = 1024;
constexpr int kMaxFlagWord = kMaxElement / 16;

// Reads a text left to right, skipping blanks; every refusal names the line.
class LineReader {
public:
    explicit LineReader(const std::string& text) : text_(text) {}

    void SkipBlanks() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])) != 0) ++pos_;
    }
    bool AtEnd() {
        SkipBlanks();
        return pos_ == text_.size();
    }
    bool Take(const std::string& token) {
        SkipBlanks();
        if (text_.compare(pos_, token.size(), token) != 0) return false;
        pos_ += token.size();
        return true;
    }
    char Peek() {
        SkipBlanks();
        return pos_ < text_.size() ? text_[pos_] : '\0';
    }
    std::string Letters() {
        SkipBlanks();
        std::string word;
        while (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_])) != 0) {
            word += static_cast<char>(std::toupper(static_cast<unsigned char>(text_[pos_++])));
        }
        return word;
    }
    int Integer() {
        std::size_t start = pos_;
        while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_])) != 0) ++pos_;
        if (start == pos_ || pos_ - start > 5) Fail("an element number");
        return std::stoi(text_.substr(start, pos_ - start));
    }
    double Number() {
        SkipBlanks();
        std::istringstream in(text_.substr(pos_));
        in.imbue(std::locale::classic());
        double value = 0.0;
        if (!(in >> value) || !std::isfinite(value)) Fail("a number");
        pos_ = in.eof() ? text_.size() : pos_ + static_cast<std::size_t>(in.tellg());
        return value;
    }
    [[noreturn]] void Fail(const std::string& expected) const {
        throw std::invalid_argument("AutomaticProgram: \"" + text_ + "\": expected " + expected + " at column " +
                                    std::to_string(pos_ + 1));
    }

private:
    const std::string& text_;
    std::size_t pos_ = 0;
};

}  // namespace

AutomaticProgram::AutomaticProgram(const std::vector<std::string>& lines) {
    for (const std::string& text : lines) lines_.push_back(Parse(text));
}

AutomaticProgram::Line AutomaticProgram::Parse(const std::string& text) {
    LineReader reader(text);
    auto operand = [&reader]() {
        Operand o;
        const std::string kind = reader.Letters();
        if (kind == "M") {
            o.kind = Kind::kFlag;
        } else if (kind == "FW") {
            o.kind = Kind::kFlagWord;
        } else if (kind == "N") {
            o.kind = Kind::kInt;
        } else if (kind == "R") {
            o.kind = Kind::kReal;
        } else {
            reader.Fail("M, FW, N or R");
        }
        o.number = reader.Integer();
        const int max = o.kind == Kind::kFlagWord ? kMaxFlagWord : kMaxElement;
        if (o.number < 1 || o.number > max) reader.Fail("a number 1.." + std::to_string(max));
        return o;
    };
    Line line;
    line.target = operand();
    if (!reader.Take(":=")) reader.Fail(":=");
    line.source = operand();
    if (!reader.AtEnd()) {
        const char op = reader.Peek();
        if (op != '+' && op != '-' && op != '*' && op != '/') reader.Fail("+, -, * or /");
        reader.Take(std::string(1, op));
        line.op = op;
        line.constant = reader.Number();
        if (op == '/' && line.constant == 0.0) reader.Fail("a divisor other than 0");
        if (!reader.AtEnd()) reader.Fail("the end of the line");
    }
    return line;
}

double AutomaticProgram::Read(const Elements& elements, const Operand& operand) {
    switch (operand.kind) {
        case Kind::kFlag: return elements.flags.Get(operand.number) ? 1.0 : 0.0;
        case Kind::kFlagWord: return elements.flags.Word(FirstFlagOf(operand.number));
        case Kind::kInt: return elements.intRegisters.GetInt(operand.number);
        case Kind::kReal: return elements.realRegisters.GetReal(operand.number);
    }
    return 0.0;
}

void AutomaticProgram::Write(Elements& elements, const Operand& operand, double value) {
    auto clamped = [value](double low, double high) {
        const double rounded = std::round(value);
        return rounded < low ? low : (rounded > high ? high : rounded);
    };
    switch (operand.kind) {
        case Kind::kFlag:
            elements.flags.Set(operand.number, value != 0.0);
            break;
        case Kind::kFlagWord:
            elements.flags.SetWord(FirstFlagOf(operand.number), static_cast<std::uint16_t>(clamped(0.0, 65535.0)));
            break;
        case Kind::kInt:
            elements.intRegisters.SetInt(
                operand.number, static_cast<std::int32_t>(clamped(std::numeric_limits<std::int32_t>::min(),
                                                                  std::numeric_limits<std::int32_t>::max())));
            break;
        case Kind::kReal:
            elements.realRegisters.SetReal(operand.number, static_cast<float>(value));
            break;
    }
}

void AutomaticProgram::Run(Elements& elements) const {
    for (const Line& line : lines_) {
        double value = Read(elements, line.source);
        switch (line.op) {
            case '+': value += line.constant; break;
            case '-': value -= line.constant; break;
            case '*': value *= line.constant; break;
            case '/': value /= line.constant; break;
            default: break;
        }
        Write(elements, line.target, value);
    }
}

}  // namespace pac::sim
