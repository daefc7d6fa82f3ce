//! The page a command writes beside its output: `index.html`, self-contained (its style and its one script inline,
//! no network: no CDN, no web font), opened with one click, and `summary.md` beside it with the same text and
//! tables for a terminal, a diff or a pull request. Pictures and files are linked by their paths relative to the
//! page, so the folder can be moved or served as it is.
//!
//! The page checks itself when it loads: its script counts the pictures that loaded and writes the count into the
//! element `#selfcheck` (`data-ok="yes"` when all did), which a headless browser's dumped DOM shows.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// A table: a header row and rows of cells (text, escaped on the page).
pub struct Table {
    pub title: String,
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
    /// a line under the table (what its figures mean)
    pub note: Option<String>,
}

/// A picture with its caption; `bar` is a heat map's scale (its maximum and unit), drawn under the caption as the
/// same gradient the picture's own bar shows.
pub struct Figure {
    pub src: String,
    pub caption: String,
    pub bar: Option<(f64, &'static str)>,
}

/// What a section holds, in order.
pub enum Block {
    Text(String),
    Figures(Vec<Figure>),
    Table(Table),
    /// links to files: (label, path relative to the page)
    Links(Vec<(String, String)>),
}

pub struct Section {
    pub title: String,
    pub blocks: Vec<Block>,
}

pub struct Page {
    pub title: String,
    pub intro: Vec<String>,
    pub sections: Vec<Section>,
}

/// Text made safe inside HTML elements and attributes.
pub fn escape(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&#39;"),
            _ => o.push(c),
        }
    }
    o
}

/// A path relative to the page, written as a URL path: each segment percent-encoded where it must be.
fn href(p: &str) -> String {
    p.split('/')
        .map(|seg| {
            seg.bytes()
                .map(|b| match b {
                    b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'_' | b'.' | b'~' => (b as char).to_string(),
                    _ => format!("%{b:02X}"),
                })
                .collect::<String>()
        })
        .collect::<Vec<_>>()
        .join("/")
}

impl Table {
    pub fn new(title: &str, header: &[&str]) -> Table {
        Table { title: title.into(), header: header.iter().map(|h| h.to_string()).collect(), rows: vec![], note: None }
    }

    pub fn markdown(&self) -> String {
        let cell = |s: &str| s.replace('|', "\\|");
        let mut t = format!("**{}**\n\n", self.title);
        let _ = writeln!(t, "| {} |", self.header.iter().map(|h| cell(h)).collect::<Vec<_>>().join(" | "));
        let _ = writeln!(t, "|{}", "---|".repeat(self.header.len()));
        for r in &self.rows {
            let _ = writeln!(t, "| {} |", r.iter().map(|c| cell(c)).collect::<Vec<_>>().join(" | "));
        }
        if let Some(n) = &self.note {
            let _ = write!(t, "\n{n}\n");
        }
        t
    }

    fn html(&self) -> String {
        let mut t = format!("<div class=\"scroll\"><table>\n<caption>{}</caption>\n<thead><tr>", escape(&self.title));
        for h in &self.header {
            let _ = write!(t, "<th>{}</th>", escape(h));
        }
        t.push_str("</tr></thead>\n<tbody>\n");
        for r in &self.rows {
            t.push_str("<tr>");
            for (i, c) in r.iter().enumerate() {
                let tag = if i == 0 { "th" } else { "td" };
                // a figure reads right-aligned on one line; words read left-aligned and wrap
                let number = c.starts_with(|x: char| x.is_ascii_digit() || x == '-' || x == '(');
                let class = if number || i == 0 { "" } else { " class=\"t\"" };
                let _ = write!(t, "<{tag}{class}>{}</{tag}>", escape(c));
            }
            t.push_str("</tr>\n");
        }
        t.push_str("</tbody>\n</table></div>\n");
        if let Some(n) = &self.note {
            let _ = writeln!(t, "<p class=\"note\">{}</p>", escape(n));
        }
        t
    }
}

const STYLE: &str = "
body { font: 15px/1.45 system-ui, -apple-system, 'Segoe UI', sans-serif; margin: 0 auto; max-width: 1280px;
       padding: 1em 2em 4em; color: #1d1f24; background: #fbfbf8; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { font-size: 1.25em; margin-top: 2.2em; border-bottom: 1px solid #d8d8d0; padding-bottom: 0.2em; }
p.intro { max-width: 60em; }
nav a { margin-right: 1em; }
.figs { display: flex; flex-wrap: wrap; gap: 14px; }
.scroll { overflow-x: auto; }
.one figure, .one figure img { width: auto; max-width: 100%; }
figure { margin: 0; width: 232px; }
figure img { width: 232px; image-rendering: pixelated; background: #0c0c10; display: block; }
figcaption { font-size: 0.85em; color: #444; margin-top: 0.3em; }
.bar { height: 10px; margin-top: 4px;
       background: linear-gradient(to right, #000 0%, #f00 33.3%, #ff0 66.7%, #fff 100%); border: 1px solid #999; }
.ends { display: flex; justify-content: space-between; font-size: 0.8em; color: #444; }
table { border-collapse: collapse; margin: 1em 0 0.3em; font-size: 0.88em; }
caption { text-align: left; font-weight: 600; padding-bottom: 0.3em; }
th, td { border: 1px solid #d0d0c8; padding: 0.25em 0.6em; text-align: right; white-space: nowrap; }
thead th { background: #efefe8; text-align: center; }
tbody th { text-align: left; font-weight: 500; }
td.t { text-align: left; white-space: normal; min-width: 14em; }
p.note { font-size: 0.85em; color: #555; max-width: 60em; margin-top: 0; }
ul.links { columns: 3; font-size: 0.9em; }
#selfcheck { font-size: 0.8em; color: #777; margin-top: 3em; }
";

/// Counts the pictures that loaded, into `#selfcheck` (a headless browser's dumped DOM shows it).
const CHECK: &str = "
window.addEventListener('load', function () {
  var imgs = Array.prototype.slice.call(document.images);
  var bad = imgs.filter(function (i) { return !(i.complete && i.naturalWidth > 0); })
                .map(function (i) { return i.getAttribute('src'); });
  var c = document.getElementById('selfcheck');
  c.textContent = 'pictures loaded: ' + (imgs.length - bad.length) + ' of ' + imgs.length +
                  (bad.length ? '; not loaded: ' + bad.join(', ') : '');
  c.setAttribute('data-ok', bad.length === 0 ? 'yes' : 'no');
});
";

impl Page {
    pub fn html(&self) -> String {
        let mut h = String::from("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
        let _ = writeln!(h, "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">");
        let _ = writeln!(h, "<title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>", escape(&self.title));
        let _ = writeln!(h, "<h1>{}</h1>", escape(&self.title));
        for p in &self.intro {
            let _ = writeln!(h, "<p class=\"intro\">{}</p>", escape(p));
        }
        h.push_str("<nav>");
        for (i, s) in self.sections.iter().enumerate() {
            let _ = write!(h, "<a href=\"#s{i}\">{}</a>", escape(&s.title));
        }
        h.push_str("</nav>\n");
        for (i, s) in self.sections.iter().enumerate() {
            let _ = writeln!(h, "<h2 id=\"s{i}\">{}</h2>", escape(&s.title));
            for b in &s.blocks {
                match b {
                    Block::Text(t) => {
                        let _ = writeln!(h, "<p>{}</p>", escape(t));
                    }
                    Block::Table(t) => h.push_str(&t.html()),
                    Block::Figures(figs) => {
                        // a figure alone (a plot) at its own size; several side by side
                        h.push_str(if figs.len() == 1 {
                            "<div class=\"figs one\">\n"
                        } else {
                            "<div class=\"figs\">\n"
                        });
                        for f in figs {
                            let _ = write!(
                                h,
                                "<figure><a href=\"{src}\"><img src=\"{src}\" alt=\"{alt}\"></a><figcaption>{cap}",
                                src = href(&f.src),
                                alt = escape(&f.caption),
                                cap = escape(&f.caption)
                            );
                            if let Some((max, unit)) = f.bar {
                                let _ = write!(
                                    h,
                                    "<div class=\"bar\"></div><div class=\"ends\"><span>0</span><span>{}</span></div>",
                                    escape(&sim::render::bar_label(max, unit))
                                );
                            }
                            h.push_str("</figcaption></figure>\n");
                        }
                        h.push_str("</div>\n");
                    }
                    Block::Links(links) => {
                        h.push_str("<ul class=\"links\">\n");
                        for (label, p) in links {
                            let _ = writeln!(h, "<li><a href=\"{}\">{}</a></li>", href(p), escape(label));
                        }
                        h.push_str("</ul>\n");
                    }
                }
            }
        }
        let _ = writeln!(h, "<p id=\"selfcheck\" data-ok=\"unknown\">pictures not checked (scripts off)</p>");
        let _ = writeln!(h, "<script>{CHECK}</script>\n</body>\n</html>");
        h
    }

    pub fn markdown(&self) -> String {
        let mut m = format!("# {}\n\n", self.title);
        for p in &self.intro {
            let _ = write!(m, "{p}\n\n");
        }
        for s in &self.sections {
            let _ = write!(m, "## {}\n\n", s.title);
            for b in &s.blocks {
                match b {
                    Block::Text(t) => {
                        let _ = write!(m, "{t}\n\n");
                    }
                    Block::Table(t) => {
                        let _ = writeln!(m, "{}", t.markdown());
                    }
                    Block::Figures(figs) => {
                        for f in figs {
                            let bar =
                                f.bar.map(|(max, unit)| format!(" (scale 0 … {})", sim::render::bar_label(max, unit)));
                            let _ = writeln!(m, "- [{}]({}){}", f.caption, href(&f.src), bar.unwrap_or_default());
                        }
                        m.push('\n');
                    }
                    Block::Links(links) => {
                        for (label, p) in links {
                            let _ = writeln!(m, "- [{label}]({})", href(p));
                        }
                        m.push('\n');
                    }
                }
            }
        }
        m
    }

    /// A page read from Markdown as the commands write it (`# ` title, `## ` sections, pipe tables, `- ` items and
    /// paragraphs), `first` put before its first section.
    pub fn from_markdown(md: &str, first: Section) -> Page {
        // what comes before the first `## ` goes into a section of its own, dropped if empty
        let lead = Section { title: "Summary".into(), blocks: vec![] };
        let mut page = Page { title: String::new(), intro: vec![], sections: vec![first, lead] };
        let mut text: Vec<String> = vec![];
        let mut table: Option<Table> = None;
        let cells = |l: &str| -> Vec<String> {
            l.trim().trim_matches('|').split(" | ").map(|c| c.trim().replace("\\|", "|")).collect()
        };
        let flush = |page: &mut Page, text: &mut Vec<String>, table: &mut Option<Table>| {
            let blocks = &mut page.sections.last_mut().expect("two sections at least").blocks;
            if !text.is_empty() {
                blocks.push(Block::Text(text.join(" ")));
                text.clear();
            }
            if let Some(t) = table.take() {
                blocks.push(Block::Table(t));
            }
        };
        for line in md.lines() {
            let l = line.trim_end();
            if let Some(t) = l.strip_prefix("# ") {
                page.title = t.to_string();
            } else if let Some(t) = l.strip_prefix("## ") {
                flush(&mut page, &mut text, &mut table);
                page.sections.push(Section { title: t.to_string(), blocks: vec![] });
            } else if l.starts_with('|') {
                if !text.is_empty() {
                    let t = table.take();
                    flush(&mut page, &mut text, &mut None);
                    table = t;
                }
                match &mut table {
                    None => {
                        let header = cells(l);
                        table = Some(Table { title: String::new(), header, rows: vec![], note: None });
                    }
                    Some(_) if l.contains("---") && l.chars().all(|c| "|-: ".contains(c)) => {}
                    Some(t) => t.rows.push(cells(l)),
                }
            } else if l.trim().is_empty() {
                flush(&mut page, &mut text, &mut table);
            } else if let Some(item) = l.strip_prefix("- ") {
                // an item of a list: a paragraph of its own
                flush(&mut page, &mut text, &mut table);
                text.push(item.to_string());
                flush(&mut page, &mut text, &mut table);
            } else {
                if table.is_some() {
                    flush(&mut page, &mut text, &mut table);
                }
                text.push(l.to_string());
            }
        }
        flush(&mut page, &mut text, &mut table);
        page.sections.retain(|s| !s.blocks.is_empty());
        page
    }

    /// Every file the page links or shows, relative to it.
    pub fn files(&self) -> Vec<&str> {
        let mut v = vec![];
        for s in &self.sections {
            for b in &s.blocks {
                match b {
                    Block::Figures(figs) => v.extend(figs.iter().map(|f| f.src.as_str())),
                    Block::Links(l) => v.extend(l.iter().map(|x| x.1.as_str())),
                    _ => {}
                }
            }
        }
        v
    }

    /// `dir/index.html` and `dir/summary.md`, each whole or not at all; an error names a linked file that is not
    /// there (a page must not point at nothing).
    pub fn write(&self, dir: &Path) -> Result<(PathBuf, PathBuf), String> {
        self.write_as(dir, "index.html", "summary.md")
    }

    /// `write`, under names of the caller's (a command whose files share a folder with another run's).
    pub fn write_as(&self, dir: &Path, html: &str, md: &str) -> Result<(PathBuf, PathBuf), String> {
        if let Some(f) = self.files().into_iter().find(|f| !dir.join(f).is_file()) {
            return Err(format!("{}: the page links {f}, which was not written", dir.join(html).display()));
        }
        let (html, md) = (dir.join(html), dir.join(md));
        synth::export::write_atomic(&html, self.html().as_bytes())?;
        synth::export::write_atomic(&md, self.markdown().as_bytes())?;
        Ok((html, md))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_markdown_report_becomes_a_title_sections_tables_and_text() {
        let md = "# R\n\nintro line\nsecond\n\n| a | b \\| c |\n| --- | --- |\n| x | 1 |\nafter\n\n## Two\n\n- item\n";
        let first = Section { title: "Plot".into(), blocks: vec![Block::Text("p".into())] };
        let p = Page::from_markdown(md, first);
        assert_eq!(p.title, "R");
        let titles: Vec<&str> = p.sections.iter().map(|s| s.title.as_str()).collect();
        assert_eq!(titles, ["Plot", "Summary", "Two"]);
        let b = &p.sections[1].blocks;
        assert!(matches!(&b[0], Block::Text(t) if t == "intro line second"));
        match &b[1] {
            Block::Table(t) => {
                assert_eq!(t.header, ["a", "b | c"]);
                assert_eq!(t.rows, [["x", "1"]]);
            }
            _ => panic!("no table"),
        }
        assert!(matches!(&b[2], Block::Text(t) if t == "after"));
        assert!(matches!(&p.sections[2].blocks[..], [Block::Text(t)] if t == "item"));
    }

    #[test]
    fn text_is_escaped_and_paths_are_encoded() {
        assert_eq!(escape("a<b & \"c\"'"), "a&lt;b &amp; &quot;c&quot;&#39;");
        assert_eq!(href("img/a b#c.png"), "img/a%20b%23c.png");
        let mut t = Table::new("x|y", &["a", "b"]);
        t.rows.push(vec!["1|2".into(), "<3>".into()]);
        assert!(t.markdown().contains("| 1\\|2 | <3> |"));
        assert!(t.html().contains("<th>1|2</th><td class=\"t\">&lt;3&gt;</td>"));
    }
}
