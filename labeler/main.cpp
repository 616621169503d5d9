// rdsf-label: a person confirms the frame analyser's candidates one by one (y / n / skip / undo / quit);
// every answer is stored before the next candidate appears, and a rerun resumes where it stopped.

#include "cli/cli.hpp"
#include "labeler/label_options.hpp"
#include "labeler/label_run.hpp"

const rdsf::cli::ProgramInfo kProgram{
    "rdsf-label", "--source SRC... --out SET [--model M [--accept P --reject P] [--ask uncertain]] [--loop [--batch N]]\n"
    "    [--budget N] [--truth boxes.csv] [--answers FILE|-] [--keep-rejected]",
    "Shows each candidate of each frame; keys: y person, n not a person, s/space skip, u/backspace undo\n"
    "(also across frames), q/Esc save and quit. Every answer is stored before the next candidate appears;\n"
    "run again on the same sources and set to resume. With --model, candidates the model is sure about are\n"
    "answered by it (journalled 'by model') and never shown. --answers takes the same keys as whitespace-separated\n"
    "tokens (y n s u q, space, backspace, esc; 'yyn' is three keys)."};

int main(int argc, char** argv) {
  return rdsf::cli::run(kProgram.name, [&] {
    namespace po = rdsf::cli::po;
    rdsf::LabelOptions o;
    rdsf::LabelOptionText text;
    po::options_description options = rdsf::label_options(o, text);
    rdsf::cli::CameraOptions camera(options, o.session.camera);
    options.add(rdsf::cli::analyser_options(o.session.analyser));
    po::variables_map values;
    if (!rdsf::cli::parse(argc, argv, kProgram, options, values, camera)) return 0;
    o.given = rdsf::cli::given_analyser_options(values);
    rdsf::apply_option_text(text, o);
    rdsf::check_options(o);
    return rdsf::run_label(o);
  });
}
