//! The CLI's display of [`Progress`]: an indicatif bar on stderr (hidden when stderr is not a
//! terminal), the one implementation every long command shares.

use gartowen::core::Progress;
use indicatif::{ProgressBar, ProgressStyle};

/// A bar whose length comes from [`Progress::start`] and whose message is the work running.
pub struct Bar(ProgressBar);

impl Bar {
    /// A bar drawn with indicatif's `template` (e.g. `"verify {msg} [{bar:30}] {pos}/{len}"`).
    pub fn new(template: &str) -> Bar {
        let bar = ProgressBar::new(0);
        bar.set_style(ProgressStyle::with_template(template).expect("a valid template"));
        Bar(bar)
    }
}

impl Progress for Bar {
    fn start(&self, total: u64, _what: &str) {
        self.0.set_length(total);
        self.0.set_position(0);
    }
    fn advance(&self, k: u64) {
        self.0.inc(k);
    }
    fn message(&self, what: &str) {
        self.0.set_message(what.to_string());
    }
    fn finish(&self) {
        self.0.finish_and_clear();
    }
}

impl Drop for Bar {
    /// An error return leaves no half-drawn bar on the terminal.
    fn drop(&mut self) {
        self.0.finish_and_clear();
    }
}
