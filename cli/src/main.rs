//! `wrc` — the command line of the wrc wheel–rail contact kernel (contract: shared/docs/cli.md).

fn main() {
    eprintln!("wrc: no subcommand implemented yet");
    std::process::exit(2);
}
