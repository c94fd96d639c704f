fn main() {
    std::process::exit(viscoroll::cli::run());
}
