mod cli;
mod hardware;
mod scene_loader;
mod tracers;
mod workstream;
