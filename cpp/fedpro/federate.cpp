// The session's federate: its life (the call in, the exception as the protocol's ExceptionData, the end), the FOM
// modules sent by content, and the conversions both ways.
#include <RTI/RTIambassadorFactory.h>
#include <ftw.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "fedpro/hla_federate.hpp"
#include "fedpro/zip.hpp"

namespace hlacore::fedpro {

std::unique_ptr<Federate> make_federate(std::string const& gateway, std::string const& password,
                                        std::function<void(std::string_view)> send_callback) {
    return std::make_unique<HlaFederate>(gateway, password, std::move(send_callback));
}

HlaFederate::HlaFederate(std::string gateway, std::string password, std::function<void(std::string_view)> send_callback)
    : gateway_(std::move(gateway)), password_(std::move(password)), send_callback_(std::move(send_callback)), rti_(api::RTIambassadorFactory().createRTIambassador()) {}

HlaFederate::~HlaFederate() { end(); }

namespace {

// The exceptions HLA 4 renamed, under their HLA 4 names: the federate's API knows those. A client that declares
// the 1516-2010 API (Pitch's 1516-2010 adapter) maps back only the first two, and knows the others by their
// 1516-2010 names.
std::string hla4_name(std::string const& name, bool api_2010) {
    static const std::pair<const char*, const char*> renamed[] = {
        {"CouldNotOpenFDD", "CouldNotOpenFOM"},
        {"ErrorReadingFDD", "ErrorReadingFOM"},
        {"InconsistentFDD", "InconsistentFOM"},
        {"InvalidTransportationType", "InvalidTransportationTypeHandle"},
        {"InvalidLocalSettingsDesignator", "ConnectionFailed"},
    };
    const std::size_t mapped = api_2010 ? 2 : std::size(renamed);
    for (std::size_t i = 0; i < mapped; ++i)
        if (name == renamed[i].first) return renamed[i].second;
    return name;
}

}  // namespace

std::string HlaFederate::call(std::string_view bytes_in) {
    pb::CallRequest request;
    pb::CallResponse response;
    auto fail = [&](std::string const& name, std::string const& details) {
        response.Clear();
        response.mutable_exceptiondata()->set_exceptionname(hla4_name(name, api_2010_));
        response.mutable_exceptiondata()->set_details(details);
    };
    if (!request.ParseFromArray(bytes_in.data(), int(bytes_in.size()))) {
        fail("RTIinternalError", "the call request does not parse as a CallRequest");
    } else {
        try {
            serve(request, response);
        } catch (Hla4Exception const& e) {
            fail(e.name, e.what());
        } catch (api::Exception const& e) {
            // hlacore's exceptions read "Name: what happened".
            const std::string text = utf8(e.what());
            const auto colon = text.find(':');
            fail(colon == std::string::npos ? "RTIinternalError" : text.substr(0, colon),
                 colon == std::string::npos ? text : text.substr(colon + 2 <= text.size() ? colon + 2 : colon + 1));
        } catch (std::exception const& e) {
            fail("RTIinternalError", e.what());
        }
    }
    return response.SerializeAsString();
}

void HlaFederate::answered(std::string_view response) {
    pb::CallbackResponse r;
    if (!r.ParseFromArray(response.data(), int(response.size())))
        std::fprintf(stderr, "fedpro: a callback response that does not parse\n");
    else if (r.has_callbackfailed())
        std::fprintf(stderr, "fedpro: the federate's callback failed: %s: %s\n", r.callbackfailed().exceptionname().c_str(),
                     r.callbackfailed().details().c_str());
}

void HlaFederate::end() {
    if (rti_) {
        try {
            if (joined_) rti_->resignFederationExecution(api::CANCEL_THEN_DELETE_THEN_DIVEST);
        } catch (api::Exception const&) {  // the federation is gone, or the gateway: nothing to resign from
        }
        joined_ = false;  // member_ stays: the status report names the federate of an ended session
        try {
            rti_->disconnect();
        } catch (api::Exception const&) {
        }
    }
    if (!modules_dir_.empty()) {
        ::nftw(modules_dir_.c_str(), [](const char* path, const struct stat*, int, struct FTW*) { return ::remove(path); }, 8,
               FTW_DEPTH | FTW_PHYS);
        modules_dir_.clear();
    }
}

// A FOM module the ambassador can read: a file's content, sent as it is or compressed (a zip archive), into a file
// of the session's own directory (its name kept, so that errors name it); a URL or path as it is.
std::wstring HlaFederate::module(pb::FomModule const& m) {
    switch (m.fomModule_case()) {
        case pb::FomModule::kUrl:
            return wide(m.url());
        case pb::FomModule::kFile:
            return module_file(m.file().name(), m.file().content());
        case pb::FomModule::kCompressedModule:
            try {
                const ZippedFile file = unzip_one(m.compressedmodule(), kMaxModuleBytes);
                return module_file(file.name, file.content);
            } catch (BadArchive const& e) {
                throw api::ErrorReadingFDD(wide(std::string("ErrorReadingFDD: ") + e.what()));
            }
        case pb::FomModule::FOMMODULE_NOT_SET:
            break;
    }
    throw api::CouldNotOpenFDD(L"CouldNotOpenFDD: a FOM module that is neither a file, a URL nor compressed");
}

std::wstring HlaFederate::module_file(std::string name, std::string const& content) {
    if (modules_dir_.empty()) {
        std::string dir = (std::getenv("TMPDIR") ? std::string(std::getenv("TMPDIR")) : "/tmp") + "/hlacore-fedpro-XXXXXX";
        if (!::mkdtemp(dir.data())) throw api::CouldNotOpenFDD(L"CouldNotOpenFDD: no directory for the modules sent");
        modules_dir_ = dir;
    }
    const auto slash = name.find_last_of('/');
    if (slash != std::string::npos) name = name.substr(slash + 1);
    if (name.empty() || name == "." || name == "..") name = "module.xml";
    std::string path = modules_dir_ + "/" + name;
    for (int n = 2; ::access(path.c_str(), F_OK) == 0; ++n) path = modules_dir_ + "/" + std::to_string(n) + "-" + name;
    std::ofstream(path, std::ios::binary) << content;
    return wide(path);
}

std::vector<std::wstring> HlaFederate::modules(pb::FomModuleSet const& set) {
    std::vector<std::wstring> out;
    for (auto const& m : set.fommodule()) out.push_back(module(m));
    return out;
}

api::AttributeHandleSet HlaFederate::attributes(pb::AttributeHandleSet const& s) const {
    api::AttributeHandleSet out;
    for (auto const& h : s.attributehandle()) out.insert(attribute(h));
    return out;
}

rti1516e::InteractionClassHandleSet HlaFederate::interaction_classes(pb::InteractionClassHandleSet const& s) const {
    rti1516e::InteractionClassHandleSet out;
    for (auto const& h : s.interactionclasshandle()) out.insert(interaction_class(h));
    return out;
}

api::FederateHandleSet HlaFederate::federates(pb::FederateHandleSet const& s) const {
    api::FederateHandleSet out;
    for (auto const& h : s.federatehandle()) out.insert(federate(h));
    return out;
}

api::DimensionHandleSet HlaFederate::dimensions(pb::DimensionHandleSet const& s) const {
    api::DimensionHandleSet out;
    for (auto const& h : s.dimensionhandle()) out.insert(dimension(h));
    return out;
}

api::RegionHandleSet HlaFederate::regions(pb::RegionHandleSet const& s) const {
    api::RegionHandleSet out;
    for (auto const& h : s.regionhandle()) out.insert(region(h));
    return out;
}

api::AttributeHandleSetRegionHandleSetPairVector HlaFederate::pairs(pb::AttributeSetRegionSetPairList const& l) const {
    api::AttributeHandleSetRegionHandleSetPairVector out;
    for (auto const& p : l.attributesetregionsetpair()) out.emplace_back(attributes(p.attributeset()), regions(p.regionset()));
    return out;
}

api::AttributeHandleValueMap HlaFederate::values(pb::AttributeHandleValueMap const& m) const {
    api::AttributeHandleValueMap out;
    for (auto const& v : m.attributehandlevalue()) out[attribute(v.attributehandle())] = data(v.value());
    return out;
}

api::ParameterHandleValueMap HlaFederate::values(pb::ParameterHandleValueMap const& m) const {
    api::ParameterHandleValueMap out;
    for (auto const& v : m.parameterhandlevalue()) out[parameter(v.parameterhandle())] = data(v.value());
    return out;
}

api::LogicalTimeFactory& HlaFederate::factory() const {
    if (!factory_) throw api::FederateNotExecutionMember(L"FederateNotExecutionMember: join first (times are the federation's)");
    return *factory_;
}

std::unique_ptr<api::LogicalTime> HlaFederate::time(pb::LogicalTime const& t) const {
    try {
        return factory().decodeLogicalTime(data(t.data()));
    } catch (api::CouldNotDecode const&) {
        throw api::InvalidLogicalTime(L"InvalidLogicalTime: " + wide(std::to_string(t.data().size())) + L" bytes are not a " +
                                      factory().getName());
    }
}

std::unique_ptr<api::LogicalTimeInterval> HlaFederate::interval(pb::LogicalTimeInterval const& t) const {
    try {
        return factory().decodeLogicalTimeInterval(data(t.data()));
    } catch (api::CouldNotDecode const&) {
        throw api::InvalidLookahead(L"InvalidLookahead: " + wide(std::to_string(t.data().size())) + L" bytes are not an interval of " +
                                    factory().getName());
    }
}

// A transportation type's handle: the 1516-2010 enumerator (HLAreliable 1, HLAbestEffort 2) as 4 big-endian bytes,
// as Pitch's clients encode theirs (and compare ours with); one byte is taken too.
api::TransportationType HlaFederate::transportation(pb::TransportationTypeHandle const& h) const {
    std::string const& d = h.data();
    const bool four = d.size() == 4 && d[0] == 0 && d[1] == 0 && d[2] == 0;
    const char value = four ? d[3] : d.size() == 1 ? d[0] : 0;
    if (value == api::RELIABLE || value == api::BEST_EFFORT) return static_cast<api::TransportationType>(value);
    throw api::InvalidTransportationType(L"InvalidTransportationType: not a handle of HLAreliable or HLAbestEffort");
}

void put(pb::TransportationTypeHandle* out, api::TransportationType type) { out->set_data(std::string{0, 0, 0, char(type)}); }

void put(pb::AttributeHandleSet* out, api::AttributeHandleSet const& s) {
    for (auto const& h : s) put(out->add_attributehandle(), h);
}
void put(pb::FederateHandleSet* out, api::FederateHandleSet const& s) {
    for (auto const& h : s) put(out->add_federatehandle(), h);
}
void put(pb::DimensionHandleSet* out, api::DimensionHandleSet const& s) {
    for (auto const& h : s) put(out->add_dimensionhandle(), h);
}
void put(pb::AttributeHandleValueMap* out, api::AttributeHandleValueMap const& m) {
    for (auto const& [h, v] : m) {
        auto* e = out->add_attributehandlevalue();
        put(e->mutable_attributehandle(), h);
        e->set_value(bytes(v));
    }
}
void put(pb::ParameterHandleValueMap* out, api::ParameterHandleValueMap const& m) {
    for (auto const& [h, v] : m) {
        auto* e = out->add_parameterhandlevalue();
        put(e->mutable_parameterhandle(), h);
        e->set_value(bytes(v));
    }
}
void put(pb::LogicalTime* out, api::LogicalTime const& t) { out->set_data(bytes(t.encode())); }
void put(pb::LogicalTimeInterval* out, api::LogicalTimeInterval const& t) { out->set_data(bytes(t.encode())); }

}  // namespace hlacore::fedpro
