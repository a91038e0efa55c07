#pragma once
// Sends std::cout and std::cerr into strings while it lives, and gives them back even
// when the code under test throws: the browser prints its summaries and refusals there.

#include <iostream>
#include <sstream>
#include <streambuf>
#include <string>

namespace test {

class CapturedOutput {
public:
    CapturedOutput() : old_out_(std::cout.rdbuf(out_.rdbuf())), old_err_(std::cerr.rdbuf(err_.rdbuf())) {}
    ~CapturedOutput() {
        std::cout.rdbuf(old_out_);
        std::cerr.rdbuf(old_err_);
    }
    CapturedOutput(const CapturedOutput&) = delete;
    CapturedOutput& operator=(const CapturedOutput&) = delete;

    std::string out() const { return out_.str(); }
    std::string err() const { return err_.str(); }

private:
    std::ostringstream out_, err_;
    std::streambuf* old_out_;
    std::streambuf* old_err_;
};

}  // namespace test
