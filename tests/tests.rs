mod cli;
mod cosim;
mod figures;
mod hardware;
mod replay;
mod scene_loader;
mod tracers;
mod workstream;
