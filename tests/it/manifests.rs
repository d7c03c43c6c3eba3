//! The Python package's workspace (python/Cargo.toml) keeps the root's dev
//! profile, table for table: its lints reuse the root's checks of the
//! libraries only while the two agree (.ci/run).

fn dev_packages(path: &str) -> toml::Value {
    let file = format!("{}/../{path}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{file}: {e}"));
    let manifest: toml::Table = toml::from_str(&text).unwrap_or_else(|e| panic!("{file}: {e}"));
    manifest["profile"]["dev"]["package"].clone()
}

#[test]
fn the_python_package_keeps_the_root_dev_profile() {
    let root = dev_packages("Cargo.toml");
    assert!(
        root.as_table()
            .is_some_and(|t| t.contains_key("stability-core"))
    );
    assert_eq!(
        dev_packages("python/Cargo.toml"),
        root,
        "copy the root Cargo.toml's [profile.dev.package.*] tables to python/Cargo.toml"
    );
}
